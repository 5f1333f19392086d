#!/usr/bin/env python3
"""Check kinetostat's --format npy files against the CSV of the same run, with a reader of
the .npy format written in Python's standard library (numpy, when it is installed, loads
every file too, and pandas makes a data frame of it).

usage: tools/npy_check.py NPY CSV [NPY CSV ...]

For every pair: the header is the format's (magic, version 1.0 for ASCII names, 2.0 or
3.0 otherwise, its length a multiple of 64, a dictionary of 'descr', 'fortran_order' and
'shape'), every field is a little-endian float64 named as a CSV column, in the CSV's order,
the CSV columns left out are only those whose cells are not numbers (a sweep's --set of a
text), the record count is the CSV's row count, the file ends with the last record, and
every value, rounded to 13 significant digits, is the CSV's text: ES20.12E3
(d.ddddddddddddE+ddd), or a whole number as the CSV writes flags and counts; an empty CSV
cell is NaN, and no other value is. Prints one line per failing pair (and at most five
differing cells); exit status 1 if any failed.
"""
import ast
import csv
import math
import struct
import sys

MAGIC = b"\x93NUMPY"


def read_npy(path):
    """(version, field names, records as tuples of floats) of an .npy file of float64 fields."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:6] != MAGIC:
        raise ValueError("not an .npy file (magic %r)" % data[:6])
    major, minor = data[6], data[7]
    if (major, minor) == (1, 0):
        length, start = struct.unpack("<H", data[8:10])[0], 10
        text = data[start:start + length].decode("latin1")
    elif (major, minor) in ((2, 0), (3, 0)):
        length, start = struct.unpack("<I", data[8:12])[0], 12
        text = data[start:start + length].decode("latin1" if major == 2 else "utf8")
    else:
        raise ValueError("version %d.%d" % (major, minor))
    if (start + length) % 64 != 0:
        raise ValueError("header of %d bytes is not a multiple of 64" % (start + length))
    if not text.endswith("\n"):
        raise ValueError("header does not end with a newline")
    header = ast.literal_eval(text)
    if sorted(header) != ["descr", "fortran_order", "shape"]:
        raise ValueError("header keys %s" % sorted(header))
    if header["fortran_order"] is not False:
        raise ValueError("fortran_order is not False")
    names = []
    for field in header["descr"]:
        if len(field) != 2 or field[1] != "<f8":
            raise ValueError("field %r is not a little-endian float64" % (field,))
        names.append(field[0])
    if len(set(names)) != len(names):
        raise ValueError("field names repeat")
    if any(ord(c) > 127 for name in names for c in name) != (major == 3):
        raise ValueError("version %d.0 for %s names" % (major, "ASCII" if major != 3 else "non-ASCII"))
    (rows,) = header["shape"]
    body = data[start + length:]
    width = 8 * len(names)
    if len(body) != rows * width:
        raise ValueError("%d bytes of records, expected %d rows x %d" % (len(body), rows, width))
    fmt = "<%dd" % len(names)
    records = [struct.unpack_from(fmt, body, k * width) for k in range(rows)]
    return (major, minor), names, records


def text13(value):
    """A value as the CSV writes a number: 13 significant digits, ES20.12E3."""
    mantissa, exponent = ("%.12E" % value).split("E")
    return "%sE%+04d" % (mantissa, int(exponent))


def is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def cell_agrees(value, cell):
    if cell == "":
        return math.isnan(value)
    if math.isnan(value) or math.isinf(value):
        return False
    if "E" not in cell and "." not in cell:  # a flag, count or override written as a whole number
        try:
            return value == int(cell)
        except ValueError:
            return value == float(cell)
    if "E" not in cell:  # an override value as given (a sweep's --vary, e.g. 0.15)
        return value == float(cell)
    return text13(value + 0.0) == cell


def check(npy_path, csv_path):
    """A list of problems (empty: the pair agrees)."""
    try:
        _, names, records = read_npy(npy_path)
    except (OSError, ValueError, SyntaxError, struct.error) as e:
        return ["%s: %s" % (npy_path, e)]
    with open(csv_path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    header, cells = rows[0], rows[1:]
    problems = []
    if len(cells) != len(records):
        return ["%d records, the CSV has %d rows" % (len(records), len(cells))]
    where = {name: i for i, name in enumerate(header)}
    missing = [n for n in names if n not in where]
    if missing:
        return ["fields not in the CSV header: %s" % missing[:5]]
    order = [where[n] for n in names]
    if order != sorted(order):
        problems.append("fields not in the CSV's order")
    for j, name in enumerate(header):
        if name not in names and all(is_number(r[j]) for r in cells):
            problems.append("CSV column %s (numbers) is not in the npy file" % name)
    bad = 0
    for k, (record, row) in enumerate(zip(records, cells)):
        for value, j in zip(record, order):
            if not cell_agrees(value, row[j]):
                bad += 1
                if bad <= 5:
                    problems.append("row %d, %s: npy %r (%s) vs CSV %r" % (k + 1, header[j], value, text13(value),
                                                                          row[j]))
    if bad > 5:
        problems.append("... %d cells differ" % bad)
    return problems


def numpy_check(npy_path, names, records):
    """numpy.load and pandas, when installed, read the same values."""
    try:
        import numpy
    except ImportError:
        return []
    a = numpy.load(npy_path)
    if list(a.dtype.names) != names or a.shape != (len(records),):
        return ["numpy reads fields %s, shape %s" % (a.dtype.names[:3], a.shape)]
    for k in range(min(len(records), 50)):
        got = [float(a[n][k]) for n in names]
        if any(not (x == y or (math.isnan(x) and math.isnan(y))) for x, y in zip(got, records[k])):
            return ["numpy reads other values in row %d" % (k + 1)]
    try:
        import pandas
    except ImportError:
        return []
    frame = pandas.DataFrame(a)
    if list(frame.columns) != names or len(frame) != len(records):
        return ["pandas.DataFrame(numpy.load(F)) has columns %s, %d rows" % (list(frame.columns)[:3], len(frame))]
    return []


def main():
    args = sys.argv[1:]
    if not args or len(args) % 2:
        sys.exit(__doc__)
    failed = 0
    for npy_path, csv_path in zip(args[::2], args[1::2]):
        problems = check(npy_path, csv_path)
        if not problems:
            _, names, records = read_npy(npy_path)
            problems = numpy_check(npy_path, names, records)
        if problems:
            failed += 1
            print("npy_check: %s against %s:" % (npy_path, csv_path))
            for p in problems:
                print("  " + p)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
