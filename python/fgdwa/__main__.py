import sys

from fgdwa.cli import main

sys.exit(main())
