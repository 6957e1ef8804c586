"""Run the benchmarks: `python -m benchmarks [NAME ...] [--out FILE]`
(default: all); with --out, what they print is also written to FILE
(`make bench` writes report/bench.txt)."""
from __future__ import annotations

import argparse
import contextlib
import importlib
import importlib.util
import sys
import time

#: The benchmark modules: the front door (start-up, questions as typed), then in the order the
#: loop runs: the world, the exploration and what it discovers, the
#: reasoning (and planning with re-planning), the general theory.
MODULES = ("startup", "typed_questions", "checking", "oracle", "exploration", "discovery",
           "knowledge", "reasoning", "replanning", "loading", "generalization",
           "hostile")


def main() -> int:
    p = argparse.ArgumentParser(prog="python -m benchmarks", description=__doc__)
    p.add_argument("names", nargs="*", choices=[[], *MODULES], metavar="NAME",
                   help=f"which benchmarks to run ({', '.join(MODULES)}; default: all)")
    p.add_argument("--out", metavar="FILE",
                   help="also write what the benchmarks print to FILE (written when they end)")
    args = p.parse_args()
    if args.out is None:
        return run(args.names or MODULES)
    copy = _Tee(sys.stdout)
    with contextlib.redirect_stdout(copy):
        code = run(args.names or MODULES)
    with open(args.out, "w", encoding="utf-8") as f:
        f.write(copy.text())
    print(f"benchmarks: {args.out}")
    return code


class _Tee:
    """Writes through to a stream and keeps a copy."""

    def __init__(self, stream) -> None:
        self.stream, self.parts = stream, []

    def write(self, s: str) -> int:
        self.parts.append(s)
        return self.stream.write(s)

    def flush(self) -> None:
        self.stream.flush()

    def text(self) -> str:
        return "".join(self.parts)


def run(names) -> int:
    for name in names:
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
