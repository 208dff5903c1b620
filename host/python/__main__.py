"""python -m wavefront: the `wavefront` command line run by the module, so that
an environment that has `pip install`ed it has the program too. The same
commands, flags, output and exit statuses (0, 1 when the machine fails, 2 when
the input is at fault, 128 + signal when a render is stopped): the module's
_main() runs the program's own dispatch (host/cli/run_command.h)."""

import sys

from wavefront import _main

sys.exit(_main(sys.argv[1:]))
