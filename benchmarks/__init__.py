"""Benchmarks: `make bench` (python -m benchmarks) runs them all.

Each module has a `main()` that prints medians and ratios measured side by
side in one run. Speed targets live here, never in timed tests.
"""
