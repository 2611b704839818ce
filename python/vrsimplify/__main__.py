"""``python -m vrsimplify IN OUT [options]``: the command-line tool, as the ``vrsimplify`` script."""
from ._cli import main

main()
