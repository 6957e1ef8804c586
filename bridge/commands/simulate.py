"""`pantarhei simulate` and `pantarhei render`: pours sampled from a
qualitative description (or given), simulated and scored, or rendered."""
from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path
from typing import Any, Optional

from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.reasoning import valid_scenes as validity
from pantarhei.bridge.commands import options
from pantarhei.bridge.errors import UserError

#: The most pours `simulate` takes at once: it holds each pour's
#: parameters, scores and record and prints them at the end, some 8 KB a
#: pour, so that 65,536 pours stay within 512 MiB.
POURS_AT_MOST = 65_536

#: The largest --params file read (bytes): JSON takes some ten times its
#: size in memory while it is parsed.
PARAMS_BYTES_AT_MOST = 16 * 2**20


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("simulate", help="simulate pours sampled from an antecedent (or given) "
                                        "and print their scores")
    source = p.add_mutually_exclusive_group(required=True)
    source.add_argument("--antecedent", "-a", metavar="P1,P2,...",
                        help="propositions describing the pour, comma-separated ('' for none)")
    source.add_argument("--params", metavar="FILE.json",
                        help="simulate the parameterizations in FILE (a list of objects with "
                             "'params': name to value)")
    p.add_argument("-n", type=options.count(1, POURS_AT_MOST), default=10,
                   help=f"parameterizations to sample (default 10, at most {POURS_AT_MOST})")
    options.add_seed(p, 0, "the sampling")
    p.add_argument("--json", action="store_true", help="print JSON")
    _simulation_options(p)
    p.set_defaults(run=simulate, pin=True)

    p = sub.add_parser("render", help="render a pour as an animated GIF (headless)")
    source = p.add_mutually_exclusive_group(required=True)
    source.add_argument("--antecedent", "-a", metavar="P1,P2,...",
                        help="propositions describing the pour, comma-separated ('' for none)")
    source.add_argument("--params", metavar="FILE.json",
                        help="render the first parameterization in FILE")
    source.add_argument("--rule", metavar="R",
                        help="render a pour of rule R's body, sampled as the pours it rests on "
                             "were drawn (see `pantarhei rules`)")
    p.add_argument("--theory", action="append", metavar="FILE",
                   help="with --rule: the theory file(s) R is in (default: the shipped theory)")
    options.add_seed(p, 0, "the sampling")
    p.add_argument("--out", default="pour.gif", help="the GIF to write (default pour.gif)")
    p.add_argument("--frames", metavar="DIR", help="also write each frame as a PNG into DIR")
    p.add_argument("--fps", type=options.count(1, 240), default=15, help="frames per simulated second (default 15)")
    p.add_argument("--size", default="480x360", help="image size WxH (default 480x360)")
    p.add_argument("--fidelity", choices=("chosen", "default"), default="chosen",
                   help="simulation settings (default: the chosen fast ones)")
    p.set_defaults(run=render, pin=True)


def _simulation_options(p: argparse.ArgumentParser) -> None:
    options.add_store(p, "results")
    p.add_argument("--no-store", action="store_true", help="neither read nor write the store")
    p.add_argument("--timeout", type=options.seconds, default=120.0,
                   help="seconds before a simulation counts as hung (default 120)")
    p.add_argument("--fidelity", choices=("chosen", "default"), default="chosen",
                   help="simulation settings: the chosen fast ones (default) or PyBullet's defaults")
    options.add_execution(p)


# ----------------------------------------------------------------------------
# input

def parse_antecedent(text: str) -> list[str]:
    """The propositions of 'P1,P2,...', known and valid together (UserError
    otherwise)."""
    from pantarhei.oracle import generative

    props = [t.strip() for t in text.split(",") if t.strip()]
    props = validity.require_valid(props)
    try:
        generative.distribution(props)
    except generative.InvalidAntecedent as e:
        raise UserError(f"invalid antecedent: {e}") from None
    return props


def read_params(path: str) -> np.ndarray:
    """The parameterizations of a JSON file: a list of objects, each with
    'params' (name to value) or itself name to value; one such object alone
    is accepted too."""
    import numpy as np

    from pantarhei.oracle import generative

    try:
        with open(path, "rb") as f:
            raw = f.read(PARAMS_BYTES_AT_MOST + 1)
        if len(raw) > PARAMS_BYTES_AT_MOST:
            raise UserError(f"{path}: larger than {PARAMS_BYTES_AT_MOST // 2**20} MiB: give at "
                            f"most {POURS_AT_MOST} pours in a smaller file")
        text = raw.decode("utf-8")
    except OSError as e:
        raise UserError(f"cannot read {path}: {e.strerror or e}") from None
    except UnicodeDecodeError as e:
        raise UserError(f"{path}: not UTF-8 text (byte {e.start + 1}); expected JSON") from None
    try:
        data = json.loads(text, parse_int=_json_int)
    except json.JSONDecodeError as e:
        raise UserError(f"{path}: malformed JSON at line {e.lineno} column {e.colno}: {e.msg}") from None
    except RecursionError:
        raise UserError(f"{path}: JSON nested too deeply for parameterizations") from None
    if isinstance(data, dict):
        data = [data]
    if not isinstance(data, list) or not data:
        raise UserError(f"{path}: expected a non-empty list of objects with 'params'")
    if len(data) > POURS_AT_MOST:
        raise UserError(f"{path}: {len(data)} parameterizations, more than the {POURS_AT_MOST} "
                        f"simulate holds at once")
    rows = []
    for k, item in enumerate(data, 1):
        if not isinstance(item, dict):
            raise UserError(f"{path}: item {k} is not an object")
        params = item.get("params", item)
        if not isinstance(params, dict):
            raise UserError(f"{path}: item {k}: 'params' is not an object")
        try:
            rows.append(generative.from_dict(params))
        except ValueError as e:
            raise UserError(f"{path}: item {k}: {e}") from None
        except (OverflowError, TypeError):
            raise UserError(f"{path}: item {k}: a number too large for any parameter") from None
    return np.array(rows)


def _json_int(text: str) -> int | float:
    """A JSON integer; one of more than 15 digits (far past any parameter's
    bounds) as a float, so that it is refused as out of bounds (or as not
    finite), not parsed digit by digit."""
    return int(text) if len(text.lstrip("-")) <= 15 else float(text)


def _parameterizations(args: argparse.Namespace, n: int) -> tuple[np.ndarray, Optional[list[str]]]:
    from pantarhei.oracle import generative

    if args.params is not None:
        return read_params(args.params), None
    props = parse_antecedent(args.antecedent)
    return generative.sample(props, n, args.seed), props


# ----------------------------------------------------------------------------
# output

def _jsonable(x: Any) -> Any:
    import numpy as np

    if isinstance(x, float) and not math.isfinite(x):
        return None
    if isinstance(x, dict):
        return {k: _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, np.generic):
        return _jsonable(x.item())
    return x


def results_json(P: np.ndarray, S: np.ndarray, records: list, errors: list) -> list[dict[str, Any]]:
    import numpy as np

    from pantarhei.oracle import generative

    names = load_vocabulary().expectation_names
    out = []
    for p, s, rec, err in zip(P, S, records, errors):
        item: dict[str, Any] = {"params": generative.to_dict(p),
                                "scores": None if np.isnan(s).any() else
                                {n: round(float(v), 4) for n, v in zip(names, s)}}
        if rec is not None:
            item["record"] = {k: v for k, v in rec.items() if k not in ("step_seconds", "seconds")}
        if err:
            item["error"] = err
        out.append(item)
    return _jsonable(out)


def _fmt(v: float) -> str:
    return str(int(v)) if float(v).is_integer() else f"{v:.1f}"


def _verdict(score: float) -> str:
    """'holds' or 'fails': the verdict of a score (bridge/verdicts.py)."""
    from pantarhei.bridge.verdicts import verdicts

    return "holds" if verdicts(score) else "fails"


def print_results(P: np.ndarray, S: np.ndarray, records: list, errors: list,
                  props: Optional[list[str]]) -> None:
    import numpy as np

    vocab = load_vocabulary()
    if props is not None:
        print(f"antecedent: {', '.join(props) if props else '(none)'}")
    for k, (p, s, rec, err) in enumerate(zip(P, S, records, errors), 1):
        print(f"\npour {k}")
        groups: dict[str, list[str]] = {}
        for par, v in zip(vocab.parameters, p):
            groups.setdefault(par.group, []).append(f"{par.name}={_fmt(v)}")
        for g, items in groups.items():
            print(f"  {g + ':':<12} {' '.join(items)}")
        if np.isnan(s).any():
            print(f"  FAILED: {err}")
            continue
        for e, v in zip(vocab.expectation_names, s):
            print(f"  {e:<32} {v:5.2f}  {_verdict(v)}")
        if rec is not None and "fractions" in rec:
            f = rec["fractions"]
            print(f"  {'liquid at the end:':<32} {f['source']:.0%} in the source, "
                  f"{f['destination']:.0%} in the destination, {f['elsewhere']:.0%} elsewhere")


# ----------------------------------------------------------------------------
# commands

def simulate(args: argparse.Namespace) -> int:
    import numpy as np

    from pantarhei.oracle.physics import PouringOracle
    from pantarhei.oracle.simulator import make_simulator
    from pantarhei.oracle.store import StoreError

    P, props = _parameterizations(args, args.n)
    if args.ray_address and args.executor != "ray":
        raise UserError("--ray-address needs --executor ray")
    try:
        sim = make_simulator(PouringOracle.name, executor=args.executor, workers=args.workers,
                             store=None if args.no_store else args.store,
                             ray_address=args.ray_address, timeout=args.timeout,
                             fidelity=args.fidelity)
    except StoreError:
        raise
    except Exception as e:  # a cluster that cannot be reached
        raise UserError(f"cannot start the simulator: {e}") from None
    with sim:
        S = sim.simulate(P, progress=not args.no_progress and sys.stderr.isatty())
        records, errors = sim.last_records, sim.last_errors
    if args.json:
        print(json.dumps(results_json(P, S, records, errors), indent=1))
    else:
        print_results(P, S, records, errors, props)
    failed = int(np.isnan(S).any(axis=1).sum())
    if failed:
        print(f"pantarhei simulate: {failed} of {len(P)} simulations failed twice", file=sys.stderr)
        return 1
    return 0


def _require_not_a_frame(params: Path, frames: Path) -> None:
    """UserError when the --params file lies in the --frames folder under a
    name render gives a frame (frame_NNNN.png): it would be written over."""
    import re

    try:
        same_dir = params.resolve().parent == frames.resolve()
    except OSError:
        return
    named = same_dir and re.fullmatch(r"frame_\d{4,}\.png", params.name)
    linked = frames.is_dir() and any(_same_file(params, f) for f in frames.glob("frame_*.png"))
    if named or linked:
        raise UserError(f"--params {params}: render writes its frames under that name in "
                        f"{frames}: give the parameters another name or the frames another folder")


def _same_file(a: Path, b: Path) -> bool:
    try:
        return a.samefile(b)
    except OSError:
        return False


def render(args: argparse.Namespace) -> int:
    from pantarhei.bridge.files import require_writable_file
    from pantarhei.oracle.fidelity import FIDELITIES
    from pantarhei.oracle.render import (FRAME_BYTES_AT_MOST, frame_bytes, frames_at_most,
                                         render as draw)

    try:
        width, height = (int(v) for v in args.size.lower().split("x"))
        if not (16 <= width <= 4096 and 16 <= height <= 4096):
            raise ValueError
    except ValueError:
        raise UserError(f"--size must be WxH with both from 16 to 4096, not '{args.size}'") from None
    if args.theory and args.rule is None:
        raise UserError("--theory goes with --rule: the theory the rule is in")
    if args.rule is not None:             # a pour of the rule's body
        from pantarhei.bridge.commands.rules import rule_antecedent

        args.antecedent = rule_antecedent(args.theory, args.rule, args.seed)
    P, props = _parameterizations(args, 1)
    if not str(args.out).lower().endswith(".gif"):
        raise UserError(f"--out must name a .gif file, not '{args.out}'")
    require_writable_file(args.out, "--out")
    if args.params:
        from pantarhei.bridge.files import require_distinct
        require_distinct({"--params": args.params, "--out": args.out})
    if args.frames:
        require_writable_file(Path(args.frames) / "frame.png", "--frames")
        if args.params:
            _require_not_a_frame(Path(args.params), Path(args.frames))
    need = frame_bytes(P[0], args.fps, width, height, FIDELITIES[args.fidelity])
    if need > FRAME_BYTES_AT_MOST:
        raise UserError(f"--size {width}x{height} at --fps {args.fps}: this pour's "
                        f"{frames_at_most(P[0], args.fps, FIDELITIES[args.fidelity])} frames would "
                        f"take {need / 2**20:.0f} MiB, more than the {FRAME_BYTES_AT_MOST // 2**20} "
                        f"MiB render holds at most: give a smaller --size or --fps")
    frames, outcome = draw(P[0], args.out, args.frames, fps=args.fps, width=width, height=height,
                           fidelity=FIDELITIES[args.fidelity])
    names = load_vocabulary().expectation_names
    print(f"wrote {args.out} ({frames} frames)" + (f" and {frames} PNGs in {args.frames}"
                                                   if args.frames else ""))
    for e, v in zip(names, outcome.scores):
        print(f"  {e:<32} {v:5.2f}  {_verdict(v)}")
    return 0
