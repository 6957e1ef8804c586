import sys

from pantarhei.bridge.cli import main

sys.exit(main())
