#!/usr/bin/python3
"""Mutation smoke test of the .mat reader (not in the suite: matio's own failures are counted,
not fixed): copies of the files in this folder with random bytes overwritten (and some cut
short) go through `ridefit analyse`. Exit 0 or 2 (read, or refused with a message) is the
contract; a signal or a hang is a finding, kept as finding_*.mat in the output folder.

    /usr/bin/python3 tests/data/mat/mutation_smoke.py build/tools/ridefit 1500 7 /tmp/mat_smoke
"""
import collections
import pathlib
import random
import subprocess
import sys


def main(ridefit, count, seed, out):
    random.seed(seed)
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    sources = sorted(pathlib.Path(__file__).parent.glob("*.mat"))
    outcomes = collections.Counter()
    for i in range(count):
        source = random.choice(sources)
        data = bytearray(source.read_bytes())
        for _ in range(random.choice([1, 2, 4, 8])):
            data[random.randrange(len(data))] = random.randrange(256)
        if random.random() < 0.2:
            data = data[: random.randrange(len(data))]
        path = out / "input.mat"
        path.write_bytes(data)
        try:
            code = subprocess.run([ridefit, "analyse", str(path)], capture_output=True,
                                  timeout=5).returncode
            outcome = "read" if code == 0 else "refused" if code == 2 else f"exit {code}"
        except subprocess.TimeoutExpired:
            outcome = "hang"
        outcomes[outcome] += 1
        if outcome not in ("read", "refused"):
            (out / f"finding_{i}_{source.stem}.mat").write_bytes(data)
    print(dict(outcomes))


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4])
