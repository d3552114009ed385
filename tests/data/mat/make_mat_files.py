#!/usr/bin/python3
"""Writes the .mat files of tests/io/mat_file_test.cc with writers independent of matio:
scipy.io.savemat (MAT v5) and h5py (MAT v7.3 = HDF5 with MATLAB's 512-byte header).

Run with Debian's /usr/bin/python3 (python3-scipy, python3-h5py):
    /usr/bin/python3 tests/data/mat/make_mat_files.py tests/data/mat
The files are committed, so the test suite needs no Python. One is not written here:
bad_damaged_dimensions.mat is a v5 file from this script with random bytes overwritten (a
mutation smoke test found it), whose header claims a 1728053448x1 `time`.

Closed forms the test checks (N = 200 samples, k = 0..N-1):
    time      = k / 1000 s        (file 'struct': k ms, stored as int32)
    body_acc  = 0.1 sin(2 pi 5 time) g           -> 9.80665 * that in m/s^2
    travel    = 10 cos(2 pi 2 time) mm, float32  -> 1e-3 * that in m
    stuck     = k mod 2, int8, unit 1     (file 'logical': k mod 3 == 0, logical)
"""
import pathlib
import sys

import h5py
import numpy as np
import scipy.io
import scipy.sparse

N = 200
k = np.arange(N)
time = k / 1000.0
body_acc = 0.1 * np.sin(2 * np.pi * 5 * time)
travel = (10 * np.cos(2 * np.pi * 2 * time)).astype(np.float32)
stuck = (k % 2).astype(np.int8)


def v5(path, variables, compressed=False, oned_as="column"):
    scipy.io.savemat(path, variables, format="5", do_compression=compressed, oned_as=oned_as)


def h5_attr_class(obj, name):
    # As MATLAB writes it: a fixed-size NULLTERM string of exactly the name's length (h5py's
    # default NULLPAD reads back one character short through matio's NULLTERM type).
    tid = h5py.h5t.C_S1.copy()
    tid.set_size(len(name))
    tid.set_strpad(h5py.h5t.STR_NULLTERM)
    aid = h5py.h5a.create(obj.id, b"MATLAB_class", tid, h5py.h5s.create(h5py.h5s.SCALAR))
    aid.write(np.array(name.encode(), dtype=f"S{len(name)}"), mtype=tid)


def h5_vector(group, name, values, **storage):
    # MATLAB is column-major: an Nx1 column vector is an HDF5 dataset of shape (1, N).
    ds = group.create_dataset(name, data=np.asarray(values, dtype=np.float64).reshape(1, -1),
                              **storage)
    h5_attr_class(ds, "double")


def h5_string(group, name, text):
    # MATLAB char: uint16 code units, a 1xL row stored as (L, 1).
    codes = np.array([ord(c) for c in text], dtype=np.uint16).reshape(-1, 1)
    ds = group.create_dataset(name, data=codes)
    h5_attr_class(ds, "char")
    ds.attrs["MATLAB_int_decode"] = np.int32(2)


def h5_struct(group, name, fields):
    g = group.create_group(name)
    h5_attr_class(g, "struct")
    g.attrs.create("MATLAB_fields",
                   [np.frombuffer(f.encode(), dtype="S1") for f in fields],
                   dtype=h5py.vlen_dtype(np.dtype("S1")))
    return g


def v73(path, fill):
    with h5py.File(path, "w", userblock_size=512) as f:
        fill(f)
    header = b"MATLAB 7.3 MAT-file, Platform: GLNXA64, Created by: make_mat_files.py HDF5 schema 1.00 ."
    block = header.ljust(116, b" ") + b"\0" * 8 + b"\x00\x02" + b"IM"
    with open(path, "r+b") as f:
        f.write(block.ljust(512, b"\0"))


def main(out):
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    units = {"time": "s", "body_acc": "g", "travel": "mm", "stuck": "1"}

    # Good files.
    v5(out / "variables_v5.mat",
       {"time": time, "body_acc": body_acc, "travel": travel, "stuck": stuck, "units": units},
       oned_as="row")
    v5(out / "struct_v5_compressed.mat",
       {"data": {"time": k.astype(np.int32), "body_acc": body_acc, "travel": travel},
        "description": np.array(["time[ms]", "body_acc[g]", "travel[mm]"], dtype=object)},
       compressed=True)
    # A char matrix, one name[unit] per row (scipy pads the rows with blanks).
    v5(out / "description_v5.mat",
       {"time": time, "body_acc": body_acc, "travel": travel,
        "description": np.array(["time[s]", "body_acc[g]", "travel[mm]"])})
    # A logical channel (MATLAB's true/false; scipy writes numpy bools so).
    v5(out / "logical_v5.mat",
       {"time": time, "body_acc": body_acc, "stuck": k % 3 == 0,
        "units": {"time": "s", "body_acc": "g", "stuck": "1"}})
    # Units inside the struct, beside the channels.
    v5(out / "struct_units_v5.mat",
       {"rec": {"time": time, "body_acc": body_acc, "units": {"time": "s", "body_acc": "g"}}})

    def variables(f):
        h5_vector(f, "time", time)
        h5_vector(f, "body_acc", body_acc)
        h5_vector(f, "travel", travel)
        u = h5_struct(f, "units", ["time", "body_acc", "travel"])
        for name in ["time", "body_acc", "travel"]:
            h5_string(u, name, units[name])
    v73(out / "variables_v73.mat", variables)

    def struct(f):
        # Chunked and deflated, as MATLAB's save -v7.3 stores larger arrays.
        d = h5_struct(f, "data", ["time", "body_acc"])
        h5_vector(d, "time", time, chunks=(1, 64), compression="gzip")
        h5_vector(d, "body_acc", body_acc, chunks=(1, 64), compression="gzip")
        h5_string(f, "description", "time[s], body_acc[g]")
    v73(out / "struct_v73_deflated.mat", struct)

    # Bad files: each breaks one rule; the test asserts the message.
    good = {"time": time, "body_acc": body_acc}
    u2 = {"time": "s", "body_acc": "g"}

    def bad(name, **changes):
        variables = dict(good, units=u2)
        variables.update(changes)
        v5(out / f"bad_{name}.mat", {k_: v for k_, v in variables.items() if v is not None})

    bad("complex", body_acc=body_acc + 1j * body_acc)
    bad("sparse", body_acc=scipy.sparse.csc_matrix(body_acc.reshape(-1, 1)))
    cell = np.empty((1, 2), dtype=object)
    cell[0, 0] = body_acc
    cell[0, 1] = body_acc
    bad("cell", body_acc=cell)
    bad("matrix", body_acc=np.vstack([body_acc, body_acc]))
    bad("empty", body_acc=np.zeros(0))
    with_nan = body_acc.copy()
    with_nan[7] = np.nan
    bad("nan", body_acc=with_nan)
    bad("mismatched", body_acc=body_acc[:-1])
    bad("unknown_unit", units={"time": "s", "body_acc": "furlong"})
    bad("no_unit", units={"time": "s"})
    bad("typo_unit", units={"time": "s", "body_acc": "g", "body_ac": "g"})
    bad("conflict", description="body_acc[m/s^2]")
    bad("char_channel", body_acc="0.1 0.2")
    back = time.copy()
    back[50] = back[49]
    bad("time_not_increasing", time=back)
    bad("struct_beside_channels", meta={"rig": "shaker 2"})
    v5(out / "bad_two_structs.mat", {"a": good, "b": good})
    v5(out / "bad_no_channels.mat", {"units": u2})
    scipy.io.savemat(out / "bad_v4.mat", good, format="4")
    (out / "bad_not_a_mat.mat").write_text("time[s],body_acc[g]\n0,1\n0.001,2\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent)
