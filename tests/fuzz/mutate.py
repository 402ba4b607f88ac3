"""Seeded mutations of parasol's inputs (decks, .mail, Gmsh 2.2 and 4.1, export files, Python
modules, MED files), for tests/fuzz/fuzz.py.

Every operator takes a `random.Random` and the file's bytes (MED: a path, edited in place
through h5py) and returns the mutated bytes and a short description of what it did, so that a
case is reproduced exactly from (seed, case number) and its description says what was done.
"""
import re

# Values that break programs that trust their input: zeros, signs, the ends of the double
# range and past them, non-numbers, integers past 32 and 64 bits, huge and negative counts.
SPECIAL_NUMBERS = [
    "0", "-0.0", "-1", "1", "2", "1e308", "-1e308", "1.7976931348623157e308", "1e309",
    "-1e309", "1e-320", "4.9e-324", "1e-308", "1e150", "-1e150", "1e154", "NaN", "nan", "inf",
    "-inf", "Infinity", "2147483647", "2147483648", "-2147483648", "-2147483649",
    "4294967296", "9223372036854775807", "9223372036854775808", "18446744073709551616",
    "1000000000", "999999999999", "-5", "1e99999", "1.0D+300", "0x10", "1e", "--1", "1..0",
    "1e-9999",
]
# Integers for counts and tags (header counts, tags, cardinalities).
SPECIAL_COUNTS = ["0", "-1", "-5", "1", "3", "1000000000", "2147483647", "2147483648",
                  "-2147483648", "999999999999", "65536", "16777216"]
# Deck expressions whose value overflows, is not a number, or guards that could overflow.
SPECIAL_EXPRESSIONS = [
    "10.0**1e308", "1e308*10.0", "-1e308*1e308", "(-1.0)**0.5", "1.0/0.0", "0.0/0.0",
    "2**63", "2**64*2**64", "2**1000000", "10**400", "1e308+1e308", "abs(-1e308)*1e308",
    "exp(1000.0)", "log(0.0)", "sqrt(-1.0)", "INST**1e999", "1e-320/1e308", "1e308/1e-308",
    "int(1e300)", "(1e154)**2", "[1.0]*1000000000",
]

NUMBER = re.compile(rb"(?<![A-Za-z_0-9.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?")
INTEGER = re.compile(rb"(?<![A-Za-z_0-9.\-])\d+(?![.\deE])")
KEYWORD = re.compile(rb"\b[A-Z][A-Z0-9_]{1,}\b")
QUOTED = re.compile(rb"'[^'\n]*'|\"[^\"\n]*\"")
KEYWORD_NUMBER = re.compile(rb"\b[A-Z][A-Z0-9_]*\s*=\s*\(?\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?)")


def _pick_match(rng, pattern, data):
    found = list(pattern.finditer(data))
    return rng.choice(found) if found else None


def _splice(data, start, end, new):
    return data[:start] + new + data[end:]


# ---- byte level -------------------------------------------------------------------------------
def flip(rng, data):
    if not data:
        return b"\x00", "flip: empty file given one NUL"
    pos = rng.randrange(len(data))
    if rng.random() < 0.5:
        new = data[pos] ^ (1 << rng.randrange(8))
    else:
        new = rng.choice(b"\x00\xff\n\r\t ()[]{}\"'=,%$#.-+eE:;\\")
    return _splice(data, pos, pos + 1, bytes([new])), "flip byte %d to 0x%02x" % (pos, new)


def truncate(rng, data):
    pos = rng.randrange(len(data) + 1) if data else 0
    return data[:pos], "truncate at byte %d of %d" % (pos, len(data))


def delete_span(rng, data):
    if not data:
        return data, "delete: empty"
    start = rng.randrange(len(data))
    n = rng.randint(1, 64)
    return data[:start] + data[start + n:], "delete %d bytes at %d" % (n, start)


def duplicate_span(rng, data):
    if not data:
        return data, "duplicate: empty"
    start = rng.randrange(len(data))
    n = rng.randint(1, 256)
    return data[:start + n] + data[start:start + n] + data[start + n:], \
        "duplicate %d bytes at %d" % (n, start)


# ---- line level -------------------------------------------------------------------------------
def line_edit(rng, data):
    lines = data.split(b"\n")
    if len(lines) < 2:
        return data + b"\n" + data, "line: doubled the one line"
    i = rng.randrange(len(lines))
    kind = rng.choice(["delete", "duplicate", "swap", "move", "blank"])
    if kind == "delete":
        del lines[i]
    elif kind == "duplicate":
        lines.insert(i, lines[i])
    elif kind == "swap":
        j = rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
        kind = "swap with %d" % (j + 1)
    elif kind == "move":
        line = lines.pop(i)
        j = rng.randrange(len(lines) + 1)
        lines.insert(j, line)
        kind = "move to %d" % (j + 1)
    else:
        lines[i] = b""
    return b"\n".join(lines), "line %d: %s" % (i + 1, kind)


def block_duplicate(rng, data, opener, closer):
    """Duplicates a whole block from a line matching `opener` to the next `closer` line."""
    lines = data.split(b"\n")
    starts = [i for i, line in enumerate(lines) if opener.match(line)]
    if not starts:
        return line_edit(rng, data)
    i = rng.choice(starts)
    j = i + 1
    while j < len(lines) and not closer.match(lines[j]):
        j += 1
    block = lines[i:j + 1]
    at = rng.choice([i, j + 1, len(lines)])
    lines[at:at] = block
    return b"\n".join(lines), "block at line %d (%d lines) duplicated at line %d" % (
        i + 1, len(block), at + 1)


# ---- token level ------------------------------------------------------------------------------
def number(rng, data):
    m = _pick_match(rng, NUMBER, data)
    if m is None:
        return flip(rng, data)
    old = m.group(0)
    roll = rng.random()
    if roll < 0.6:
        new = rng.choice(SPECIAL_NUMBERS).encode()
    elif roll < 0.8:
        try:
            value = float(old.replace(b"D", b"e").replace(b"d", b"e"))
            new = repr(value * 10.0 ** rng.choice([-300, -30, -8, -1, 1, 8, 30, 150, 300])
                       ).encode()
        except (ValueError, OverflowError):
            new = b"1e308"
    elif roll < 0.9:
        new = b"-" + old.lstrip(b"+-")
    else:
        new = old + old
    return _splice(data, m.start(), m.end(), new), "number at byte %d: %s -> %s" % (
        m.start(), old.decode("latin-1"), new.decode("latin-1"))


def keyword_number(rng, data):
    """Replaces the (first) number given to a deck keyword (E=2.0E+11, NPREC=9,
    VALE=(1.0E+04, ...)) by a special value: the values handlers must range-check."""
    found = list(KEYWORD_NUMBER.finditer(data))
    if not found:
        return number(rng, data)
    m = rng.choice(found)
    old = m.group(1)
    if rng.random() < 0.85:
        new = rng.choice(SPECIAL_NUMBERS).encode()
    else:
        new = rng.choice(SPECIAL_EXPRESSIONS).encode()
    return _splice(data, m.start(1), m.end(1), new), "keyword value at byte %d: %s -> %s" % (
        m.start(1), m.group(0).decode("latin-1"), new.decode("latin-1"))


def count(rng, data, header):
    """Replaces an integer of the line after a line matching `header` (a section's counts)."""
    lines = data.split(b"\n")
    heads = [i for i, line in enumerate(lines) if header.match(line)]
    if not heads:
        return number(rng, data)
    i = rng.choice(heads) + 1
    # skip to the first line of the section with integers (Gmsh 4.1 headers are one line)
    if i >= len(lines):
        return number(rng, data)
    found = list(INTEGER.finditer(lines[i]))
    if not found:
        return number(rng, data)
    m = rng.choice(found)
    old = m.group(0)
    if rng.random() < 0.7:
        new = rng.choice(SPECIAL_COUNTS).encode()
    else:
        new = str(int(old) + rng.choice([-2, -1, 1, 2, 1000])).encode()
    lines[i] = _splice(lines[i], m.start(), m.end(), new)
    return b"\n".join(lines), "count on line %d: %s -> %s" % (
        i + 1, old.decode(), new.decode())


def keyword(rng, data, vocabulary):
    m = _pick_match(rng, KEYWORD, data)
    if m is None or not vocabulary:
        return flip(rng, data)
    new = rng.choice(vocabulary)
    return _splice(data, m.start(), m.end(), new), "keyword at byte %d: %s -> %s" % (
        m.start(), m.group(0).decode(), new.decode())


def quoted(rng, data, vocabulary):
    """Replaces a quoted text (a group name, MODELISATION, FORMAT ...) by another word."""
    m = _pick_match(rng, QUOTED, data)
    if m is None:
        return keyword(rng, data, vocabulary)
    q = m.group(0)[:1]
    new = q + rng.choice(vocabulary + [b"", b"X" * 300, b"\xc3\xa9", b"%s"]) + q
    return _splice(data, m.start(), m.end(), new), "text at byte %d: %s -> %s" % (
        m.start(), m.group(0).decode("latin-1"), new.decode("latin-1"))


def expression(rng, data):
    m = _pick_match(rng, NUMBER, data)
    if m is None:
        return flip(rng, data)
    new = rng.choice(SPECIAL_EXPRESSIONS).encode()
    return _splice(data, m.start(), m.end(), new), "expression at byte %d: %s -> %s" % (
        m.start(), m.group(0).decode(), new.decode())


# ---- geometry of text meshes ------------------------------------------------------------------
MAIL_NODE = re.compile(rb"^\s*(N\w+)\s+(\S+)\s+(\S+)(?:\s+(\S+))?\s*$")


def mail_geometry(rng, data):
    """Makes two nodes coincide or lifts a plate node out of its plane (a warped cell)."""
    lines = data.split(b"\n")
    nodes = [i for i, line in enumerate(lines) if MAIL_NODE.match(line)]
    if len(nodes) < 2:
        return number(rng, data)
    i, j = rng.sample(nodes, 2)
    mi, mj = MAIL_NODE.match(lines[i]), MAIL_NODE.match(lines[j])
    if rng.random() < 0.5:
        coords = [g for g in mj.groups()[1:] if g is not None]
        lines[i] = mi.group(1) + b" " + b" ".join(coords)
        what = "node %s moved onto %s" % (mi.group(1).decode(), mj.group(1).decode())
    else:
        coords = [g for g in mi.groups()[1:] if g is not None]
        k = len(coords) - 1
        try:
            coords[k] = repr(float(coords[k]) + rng.choice([1e-9, 1e-3, 0.05, 0.5, 10.0])
                             ).encode()
        except ValueError:
            return number(rng, data)
        lines[i] = mi.group(1) + b" " + b" ".join(coords)
        what = "node %s lifted out of its plane" % mi.group(1).decode()
    return b"\n".join(lines), what


# ---- MED through h5py -------------------------------------------------------------------------
def med_content(rng, path):
    """Edits a MED file in place at the HDF5 content level: numbers in datasets, counts in
    the NBR attributes, datasets removed, duplicated or replaced by others of another
    length, names overwritten. Returns the description."""
    import h5py
    import numpy

    with h5py.File(path, "r+") as f:
        datasets, groups = [], []

        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                datasets.append(name)
            else:
                groups.append(name)
        f.visititems(visit)
        mesh_sets = [d for d in datasets if d.startswith(("ENS_MAA", "FAS"))] or datasets
        if not mesh_sets:
            return "no dataset to edit"
        name = rng.choice(mesh_sets)
        ds = f[name]
        kind = rng.choice(["values", "values", "nbr", "nbr", "resize", "delete", "attr",
                           "group_delete", "dtype"])
        if kind == "values" and ds.size > 0 and ds.dtype.kind in "fi":
            data = ds[()]
            flat = data.reshape(-1)
            k = rng.randrange(flat.size)
            if ds.dtype.kind == "f":
                flat[k] = rng.choice([numpy.nan, numpy.inf, -numpy.inf, 1e308, -1e308, 0.0,
                                      1e-320, flat[(k + 1) % flat.size]])
            else:
                info = numpy.iinfo(ds.dtype)
                flat[k] = rng.choice([0, -1, info.max, info.min, 1000000000 % info.max,
                                      flat[(k + 1) % flat.size], flat.size + 1])
            ds[()] = data
            return "%s[%d] set to %r" % (name, k, flat[k])
        if kind == "nbr" and "NBR" in ds.attrs:
            old = int(ds.attrs["NBR"])
            new = rng.choice([0, -1, old - 1, old + 1, 2 * old, 1000000000, 2147483647])
            ds.attrs.modify("NBR", numpy.int32(new) if abs(new) < 2**31 else numpy.int64(new))
            return "%s NBR %d -> %d" % (name, old, new)
        if kind == "resize" and ds.dtype.kind in "fi" and ds.ndim == 1:
            data = ds[()]
            n = rng.choice([0, 1, max(0, data.size - 1), data.size + 1, 2 * data.size])
            new = numpy.resize(data, n) if data.size else numpy.zeros(n, ds.dtype)
            attrs = dict(ds.attrs)
            del f[name]
            out = f.create_dataset(name, data=new.astype(data.dtype))
            for key, value in attrs.items():
                out.attrs[key] = value
            return "%s resized %d -> %d (attributes kept)" % (name, data.size, n)
        if kind == "delete":
            del f[name]
            return "%s deleted" % name
        if kind == "attr" and len(ds.attrs):
            key = rng.choice(list(ds.attrs.keys()))
            del ds.attrs[key]
            return "%s attribute %s deleted" % (name, key)
        if kind == "group_delete" and groups:
            g = rng.choice([g for g in groups if g.count("/") >= 1] or groups)
            del f[g]
            return "group %s deleted" % g
        if kind == "dtype" and ds.dtype.kind in "fi":
            data = ds[()]
            attrs = dict(ds.attrs)
            del f[name]
            other = numpy.float64 if ds.dtype.kind == "i" else numpy.int32
            out = f.create_dataset(name, data=data.astype(other))
            for key, value in attrs.items():
                out.attrs[key] = value
            return "%s stored as %s" % (name, numpy.dtype(other).name)
        # fallback: a group attribute of the mesh (dimension, type) given an odd value
        mesh_groups = [g for g in groups if g.startswith("ENS_MAA/")] or groups
        g = f[rng.choice(mesh_groups)]
        if len(g.attrs):
            key = rng.choice(list(g.attrs.keys()))
            value = g.attrs[key]
            if isinstance(value, (bytes, numpy.bytes_)):
                g.attrs[key] = numpy.bytes_(b"\xff" * rng.choice([0, 1, 64, 200]))
            else:
                g.attrs[key] = rng.choice([-1, 0, 4, 1000000000])
            return "%s attribute %s changed" % (g.name, key)
        return "nothing changed"


def main(argv):
    """`mutate.py med PATH SEED`: med_content in a process of its own (HDF5 may crash on a
    damaged file: the fuzzer must not). Prints the description."""
    import random
    if len(argv) == 4 and argv[1] == "med":
        print(med_content(random.Random(int(argv[3])), argv[2]))
        return 0
    if len(argv) == 3 and argv[1] == "finite":
        return finite_report(argv[2])
    print("usage: mutate.py med PATH SEED | finite PATH")
    return 2


def finite_report(path):
    """`mutate.py finite PATH`: the float datasets of an HDF5 file holding NaN or Inf, one per
    line (none: nothing printed); exit 3 when the file cannot be read."""
    import h5py
    import numpy
    bad = []
    try:
        with h5py.File(path, "r") as f:
            def visit(name, obj):
                if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f":
                    if not numpy.all(numpy.isfinite(obj[()])):
                        bad.append(name)
            f.visititems(visit)
    except Exception as exc:
        print("unreadable result file (%s)" % exc)
        return 3
    for name in bad:
        print(name)
    return 0


if __name__ == "__main__":
    import sys
    sys.exit(main(sys.argv))
