"""``python3 -m tumble run|sweep|find|inertia|plot ...``: the tumble command line, the same
commands, options, output and exit statuses (``python3 -m tumble --help``)."""

import sys

from tumble import _tumble


def main() -> int:
    return _tumble.run_cli(["tumble", *sys.argv[1:]])


if __name__ == "__main__":
    sys.exit(main())
