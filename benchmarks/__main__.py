"""Run the benchmarks: `python -m benchmarks [NAME ...]` (default: all)."""
from __future__ import annotations

import argparse
import importlib
import importlib.util
import sys
import time

#: The benchmark modules: the front door (start-up), then in the order the
#: loop runs: the world, the exploration and what it discovers, the
#: reasoning, the general theory.
MODULES = ("startup", "oracle", "exploration", "discovery", "reasoning", "loading", "generalization")


def main() -> int:
    p = argparse.ArgumentParser(prog="python -m benchmarks", description=__doc__)
    p.add_argument("names", nargs="*", choices=[[], *MODULES], metavar="NAME",
                   help=f"which benchmarks to run ({', '.join(MODULES)}; default: all)")
    args = p.parse_args()
    for name in args.names or MODULES:
        if importlib.util.find_spec(f"benchmarks.{name}") is None:
            print(f"== {name}: no benchmark yet", flush=True)
            continue
        print(f"== {name}", flush=True)
        start = time.perf_counter()
        importlib.import_module(f"benchmarks.{name}").main()
        print(f"== {name}: {time.perf_counter() - start:.1f} s\n", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
