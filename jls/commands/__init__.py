"""Bodies of the ``jls`` subcommands too large for :mod:`jls.cli`, one module each, with
the helpers every command shares (:mod:`jls.commands.common`). :mod:`jls.cli` builds the
parser and dispatches; a command module registers its own arguments (``add_parser``)."""
