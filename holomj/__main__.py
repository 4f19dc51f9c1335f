"""``python -m holomj`` runs the command line."""

from holomj.cli import main

main()
