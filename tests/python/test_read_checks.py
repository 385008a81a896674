"""Damaged and hostile files (docs/robustness.md, "HDF5 files"): random bytes flipped in a
run file and in a comparison file, a small file declaring a huge dataset, external links,
arrays of the wrong type or length. Every reader (reelsim.read here, the CLI's `plot`
through the same C reader) either refuses the file (InputError / exit 2, naming the file
and what is damaged) or reads back exactly the original values: never a changed curve,
never a crash."""

import os
import resource
import shutil
import subprocess
import time

import h5py
import numpy as np
import pytest

from conftest import CLI, cli, cli_run, scene

SEED = 36
FIELDS = ("radius", "sigma_r", "sigma_theta", "pressure", "wound_on_tension", "web_tension",
          "nip_load")


def flipped(src, dst, rng, count, region=None):
    """A copy of src with `count` random bytes flipped (xor a random nonzero byte), at
    offsets drawn from `region` (a range) or from the whole file."""
    data = bytearray(open(src, "rb").read())
    where = region if region is not None else range(len(data))
    for _ in range(count):
        i = int(rng.choice(where))
        data[i] ^= int(rng.integers(1, 256))
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    with open(dst, "wb") as f:
        f.write(data)


def same(a, b):
    for k in FIELDS:
        if not np.array_equal(getattr(a, k), getattr(b, k), equal_nan=True):
            return k
    if not (a.core_pressure == b.core_pressure and a.title == b.title
            and a.complete == b.complete and a.wall_seconds == b.wall_seconds):
        return "a scalar"
    return None


@pytest.fixture(scope="module")
def run_file(tmp_path_factory):
    d = tmp_path_factory.mktemp("orig")
    out = d / "run.h5"
    cli_run(scene("tests/cli/scenes/small.yaml"), out)
    return out


def regions(path):
    """The whole file, and its first and last 4 KiB (superblock, root object header,
    group and chunk indexes: the metadata)."""
    n = os.path.getsize(path)
    head = range(0, min(4096, n))
    tail = range(max(0, n - 4096), n)
    return {"anywhere": None, "metadata": np.concatenate([np.arange(head.start, head.stop),
                                                          np.arange(tail.start, tail.stop)])}


def test_flips_python(reelsim, run_file, tmp_path):
    orig = reelsim.read(run_file)
    rng = np.random.default_rng(SEED)
    counts = {"refused": 0, "identical": 0}
    for name, region in regions(run_file).items():
        for i in range(40):
            copy = tmp_path / f"{name}{i}" / "run.h5"
            flipped(run_file, str(copy), rng, 20 if region is None else 3, region)
            try:
                got = reelsim.read(copy)
            except reelsim.InputError as e:
                assert str(copy) in e.message, e.message
                counts["refused"] += 1
                continue
            diff = same(orig, got)
            assert diff is None, f"{copy}: {diff} read back changed"
            counts["identical"] += 1
    print(counts)
    assert counts["refused"] > 40  # most copies are damaged where it matters


def test_flips_cli_plot(run_file, tmp_path):
    """`reelsim plot` of damaged run and comparison files: exit 2 naming the file, or
    exactly the original figures (PNG bytes)."""
    cmp = tmp_path / "orig" / "cmp.h5"
    cmp.parent.mkdir()
    p = cli("compare", scene("tests/cli/scenes/small.yaml"), scene("cases/newsprint-taper.yaml"),
            "-o", str(cmp), "--quiet")
    assert p.returncode == 0, p.stderr
    rng = np.random.default_rng(SEED + 1)
    for src in (run_file, cmp):
        ref = tmp_path / ("ref-" + src.stem)
        p = cli("plot", str(src), "-o", str(ref), "--quiet")
        assert p.returncode == 0, p.stderr
        pngs = sorted(os.listdir(ref))
        outcomes = []
        for name, region in regions(src).items():
            for i in range(6):
                copy = tmp_path / f"{src.stem}-{name}{i}" / src.name
                flipped(src, str(copy), rng, 20 if region is None else 3, region)
                out = copy.parent / "png"
                p = cli("plot", str(copy), "-o", str(out), "--quiet")
                assert p.returncode in (0, 2), (copy, p.returncode, p.stderr)
                if p.returncode == 2:
                    assert str(copy) in p.stderr, p.stderr
                    outcomes.append(2)
                    continue
                assert sorted(os.listdir(out)) == pngs
                for png in pngs:
                    a, b = (ref / png).read_bytes(), (out / png).read_bytes()
                    assert a == b, f"{copy}: {png} differs from the original's"
                outcomes.append(0)
        print(src.name, outcomes)
        assert outcomes.count(2) >= 6


def _limit_memory():
    resource.setrlimit(resource.RLIMIT_AS, (1 << 30, 1 << 30))


def test_oversize_declaration(reelsim, tmp_path):
    """A file of some 400 kB declaring 2.5e8 values (2 GB) per dataset: refused at once,
    before anything of that size is allocated (plot runs under a 1 GiB address-space
    limit and must still exit 2, not 1 for out of memory)."""
    path = tmp_path / "big.h5"
    n = 250_000_000
    with h5py.File(path, "w", libver="latest") as f:
        f.attrs.create("program", np.bytes_(b"reelsim"))
        for k in ("layers/radius", "layers/wound_on_tension", "final/sigma_r",
                  "final/sigma_theta", "final/pressure", "final/radius"):
            d = f.create_dataset(k, shape=(n,), maxshape=(None,), dtype="f8", chunks=(32768,),
                                 compression="gzip", fletcher32=True)
            d[:32768 if k == "layers/radius" else 10] = np.random.default_rng(1).random(
                32768 if k == "layers/radius" else 10)
        f.create_dataset("final/core_pressure", data=1.0)
    assert os.path.getsize(path) < 600_000
    t = time.monotonic()
    with pytest.raises(reelsim.InputError, match="declares 250000000 values"):
        reelsim.read(path)
    p = subprocess.run([CLI, "plot", str(path), "-o", str(tmp_path / "p")], capture_output=True,
                       text=True, preexec_fn=_limit_memory)
    took = time.monotonic() - t
    assert p.returncode == 2, p.stderr
    assert "declares 250000000 values" in p.stderr and str(path) in p.stderr, p.stderr
    assert took < 5.0, took


def _copy(run_file, tmp_path, name):
    dst = tmp_path / name
    shutil.copy(run_file, dst)
    return dst


def _replace(path, key, data):
    with h5py.File(path, "a") as f:
        del f[key]
        f.create_dataset(key, data=data, chunks=True, fletcher32=True)


def test_foreign_filter(reelsim, run_file, tmp_path):
    """A dataset compressed with a filter reelsim never writes (h5py's LZF, filter 32000,
    which HDF5 itself does not have: a reader would look for it on the plugin path) is
    refused before its values are read, by the Python reader and by `reelsim plot`."""
    path = _copy(run_file, tmp_path, "lzf.h5")
    with h5py.File(path, "a") as f:
        data = f["final/sigma_r"][...]
        del f["final/sigma_r"]
        f.create_dataset("final/sigma_r", data=data, compression="lzf", fletcher32=True)
    with pytest.raises(reelsim.InputError, match="filtered by HDF5 filter 32000"):
        reelsim.read(path)
    p = cli("plot", str(path), "-o", str(tmp_path / "p-lzf"))
    assert p.returncode == 2 and "filtered by HDF5 filter 32000" in p.stderr, p.stderr


def test_external_and_soft_links(reelsim, run_file, tmp_path):
    other = tmp_path / "other.h5"
    with h5py.File(other, "w") as f:
        f["x"] = np.arange(10.0)
    for kind, link in (("external", h5py.ExternalLink(str(other), "/x")),
                       ("soft", h5py.SoftLink("/layers/radius"))):
        path = _copy(run_file, tmp_path, f"{kind}.h5")
        with h5py.File(path, "a") as f:
            del f["final/sigma_r"]
            f["final/sigma_r"] = link
        with pytest.raises(reelsim.InputError, match="external or soft link"):
            reelsim.read(path)
        p = cli("plot", str(path), "-o", str(tmp_path / f"p-{kind}"))
        assert p.returncode == 2 and "external or soft link" in p.stderr, p.stderr


def test_types_lengths_and_complete(reelsim, run_file, tmp_path):
    orig = reelsim.read(run_file)
    n = orig.layers
    cases = {"integers": np.arange(n, dtype=np.int64), "neither": np.zeros(n, dtype=bool)}
    for what, data in cases.items():
        path = _copy(run_file, tmp_path, f"{what}.h5")
        _replace(path, "layers/nip_load", data)
        with pytest.raises(reelsim.InputError, match=f"'/layers/nip_load' holds {what}"):
            reelsim.read(path)
    path = _copy(run_file, tmp_path, "complex.h5")
    _replace(path, "final/sigma_theta", np.zeros(n, dtype=complex))
    with pytest.raises(reelsim.InputError, match="'/final/sigma_theta' holds neither"):
        reelsim.read(path)
    path = _copy(run_file, tmp_path, "short.h5")
    _replace(path, "final/sigma_theta", np.zeros(n - 1))
    with pytest.raises(reelsim.InputError, match=f"holds {n - 1} values but /layers/radius {n}"):
        reelsim.read(path)
    path = _copy(run_file, tmp_path, "partial.h5")
    with h5py.File(path, "a") as f:
        f.attrs["complete"] = np.int64(0)
    assert orig.complete and not reelsim.read(path).complete
