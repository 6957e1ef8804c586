"""oracle/ray_executor.py: the Ray executor on a local Ray (2 CPUs,
loopback): the same results as the local workers, the same handling of
crashes and hangs, and no port open beyond loopback. One Ray for the whole
file (the module-scoped fixture), so these tests stay together."""
from __future__ import annotations

import ipaddress
import json
import os

import numpy as np
import pytest

from pantarhei.oracle.faults import FaultyOracle
from pantarhei.oracle.ray_executor import RayExecutor
from pantarhei.oracle.generative import sample
from pantarhei.oracle.physics import PouringOracle
from pantarhei.oracle.simulator import Simulator, make_simulator
from pantarhei.theory.lexicon import load_vocabulary

from .pours import CENTRED_LOW_TIPPED, HEAVY_DROP, pour

pytestmark = pytest.mark.slow
COUNT = load_vocabulary().parameter("particle_count").index


@pytest.fixture(scope="module")
def ray_executor():
    ex = RayExecutor(address=None, workers=2)
    assert ex.workers == 2
    yield ex
    ex.close()


def test_ray_gives_the_same_scores_as_this_machine(ray_executor, tmp_path):
    P = np.array([pour(**CENTRED_LOW_TIPPED), pour(**HEAVY_DROP)])
    with make_simulator("pybullet", executor="local", workers=2, store=None) as local:
        here = local.simulate(P)
    sim = Simulator(PouringOracle(), ray_executor, store=None, timeout=120)
    assert np.array_equal(sim.simulate(P), here)
    assert all(r is not None and "fractions" in r for r in sim.last_records)


def test_ray_records_a_crash_and_a_hang_as_failed(ray_executor):
    P = sample([], 4, seed=3)
    P[:, COUNT] = [50, 51, 52, 53]
    # the hang never ends; the time limit leaves a loaded machine's Ray time
    # to start a worker for each of the others (3 s did not, under load)
    sim = Simulator(FaultyOracle(crash=[51], hang=[52]), ray_executor, store=None, timeout=20)
    S = sim.simulate(P)
    assert np.isnan(S[1]).all() and np.isnan(S[2]).all()
    assert "timed out" in sim.last_errors[2]
    good = FaultyOracle()
    assert np.array_equal(S[[0, 3]], np.array([good.score(P[i]).scores for i in (0, 3)]))


def _listening() -> dict[int, str]:
    """Socket inode -> address of every TCP socket listening on this machine."""
    found = {}
    for name, v6 in (("tcp", False), ("tcp6", True)):
        try:
            with open(f"/proc/net/{name}") as f:
                lines = f.read().splitlines()[1:]
        except OSError:
            continue
        for line in lines:
            fields = line.split()
            if fields[3] != "0A":       # LISTEN
                continue
            raw = bytes.fromhex(fields[1].split(":")[0])
            if v6:      # four little-endian words
                raw = b"".join(raw[i:i + 4][::-1] for i in range(0, 16, 4))
            else:
                raw = raw[::-1]
            found[int(fields[9])] = str(ipaddress.ip_address(raw))
    return found


def _this_process_and_descendants() -> list[int]:
    children: dict[int, list[int]] = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as f:
                    ppid = int(f.read().rsplit(")", 1)[1].split()[1])
            except OSError:
                continue
            children.setdefault(ppid, []).append(int(entry))
    todo, pids = [os.getpid()], []
    while todo:
        pid = todo.pop()
        pids.append(pid)
        todo += children.get(pid, [])
    return pids


def _loopback(address: str) -> bool:
    ip = ipaddress.ip_address(address)
    return ip.is_loopback or bool(getattr(ip, "ipv4_mapped", None) and ip.ipv4_mapped.is_loopback)


def test_a_local_ray_listens_on_loopback_only(ray_executor):
    """Every port opened by the local Ray (the GCS, the raylet, the workers,
    the runtime-environment agent, this driver) is on loopback."""
    Simulator(PouringOracle(), ray_executor, store=None, timeout=120).simulate(
        np.array([pour(**CENTRED_LOW_TIPPED), pour(**HEAVY_DROP)]))
    sockets = _listening()
    ports = []
    for pid in _this_process_and_descendants():
        try:
            fds = os.listdir(f"/proc/{pid}/fd")
        except OSError:
            continue
        for fd in fds:
            try:
                target = os.readlink(f"/proc/{pid}/fd/{fd}")
            except OSError:
                continue
            if target.startswith("socket:[") and int(target[8:-1]) in sockets:
                ports.append((pid, sockets[int(target[8:-1])]))
    assert len({pid for pid, _ in ports}) >= 4      # driver, GCS, raylet, workers: they listen
    assert [p for p in ports if not _loopback(p[1])] == []


def test_the_ray_executor_from_the_command_line(cli):
    args = ("simulate", "--antecedent", "pour_mid_height,pour_near_rim,pour_steeply_tilted",
            "-n", "3", "--seed", "1", "--json", "--no-store", "--no-progress", "--workers", "2")
    ray = cli(*args, "--executor", "ray")
    assert ray.code == 0, ray.err
    local = cli(*args, "--executor", "local")
    assert local.code == 0, local.err
    assert [r["scores"] for r in json.loads(ray.out)] == [r["scores"] for r in json.loads(local.out)]
    assert all(r["scores"] is not None for r in json.loads(ray.out))


def test_a_ray_address_that_does_not_answer_is_refused_in_seconds_naming_it():
    import socket

    from pantarhei.oracle.ray_executor import reach

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        free = s.getsockname()[1]               # closed again: nothing listens there
    with pytest.raises(RuntimeError, match=rf"cannot reach a Ray cluster at 127.0.0.1:{free}: "):
        reach(f"127.0.0.1:{free}", timeout=2)
    with pytest.raises(RuntimeError, match="no such host nosuchhost.invalid"):
        reach("ray://nosuchhost.invalid:10001", timeout=2)
    with socket.socket() as s:                  # something listens and says nothing
        s.bind(("127.0.0.1", 0))
        s.listen()
        with pytest.raises(RuntimeError, match="no answer"):
            reach(f"127.0.0.1:{s.getsockname()[1]}", timeout=1)
    reach("auto")


@pytest.mark.parametrize("answer, ray", [(b"HTTP/1.1 400 Bad Request\r\n\r\n", False),
                                         (bytes([0, 0, 6, 0x4, 0, 0, 0, 0, 0]) + b"\0" * 6, True)])
def test_a_ray_address_is_refused_unless_it_speaks_grpc(answer, ray):
    """A port that answers but is not Ray's (a web server) is refused in
    seconds, before ray.init waits on it; one that answers the HTTP/2
    preface with a SETTINGS frame, as Ray's gRPC servers do, passes."""
    import socket
    import threading

    from pantarhei.oracle.ray_executor import HTTP2_PREFACE, reach

    heard = []
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen()

        def serve():
            conn, _ = s.accept()
            with conn:
                heard.append(conn.recv(len(HTTP2_PREFACE)))
                conn.sendall(answer)

        t = threading.Thread(target=serve, daemon=True)
        t.start()
        address = f"127.0.0.1:{s.getsockname()[1]}"
        if ray:
            reach(address, timeout=5)
        else:
            with pytest.raises(RuntimeError, match="does not speak gRPC"):
                reach(address, timeout=5)
        t.join(5)
    assert heard == [HTTP2_PREFACE]
