import sys
from pathlib import Path

# the oracle helpers (lcnc, compare, generate) are plain modules next to the tests
sys.path.insert(0, str(Path(__file__).resolve().parent))
