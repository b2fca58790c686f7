"""Helpers for the case evaluate scripts: read what spoutFoam and OpenFOAM
function objects write (fields and dictionaries: foamfile), draw PNG plots
with gnuplot, and report checks.

Standard library only, so a fresh machine needs nothing beyond python3.
"""
import csv
import math
import os
import re
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET
import zlib


def read_dat(path):
    """An OpenFOAM function-object .dat file: (header dict, rows of floats).

    Vector entries like '(1 2 3)' become three numbers in the row."""
    header, rows = {}, []
    with open(path) as f:
        for line in f:
            if line.startswith('#'):
                m = re.match(r'#\s*([^:]+?)\s*:\s*(.*)', line)
                if m:
                    header[m.group(1)] = m.group(2).strip()
                continue
            numbers = line.replace('(', ' ').replace(')', ' ').split()
            if numbers:
                rows.append([float(x) for x in numbers])
    return header, rows


def function_object_file(case, name, filename):
    """The newest <case>/postProcessing/<name>/<time>/<filename>; restarts
    write a new time directory, so rows from all of them are joined."""
    base = os.path.join(case, 'postProcessing', name)
    times = sorted(os.listdir(base), key=float)
    return [os.path.join(base, t, filename) for t in times]


def earlier(t, t0):
    """Whether time t lies before t0 by more than rounding: a restart adds its
    time steps to the written start time, so the same instant may come out a
    few units in the last place away from the interrupted run's value."""
    return t < t0 - 1e-9 * max(abs(t0), 1e-6)


def read_function_object(case, name, filename):
    """Rows of a function object's files in every time directory; a restart's
    rows replace those the interrupted run wrote from the restart's first time."""
    header, rows = {}, []
    for path in function_object_file(case, name, filename):
        h, r = read_dat(path)
        header.update(h)
        if rows and r:
            rows = [row for row in rows if earlier(row[0], r[0][0])]
        rows.extend(r)
    return header, rows


def read_coupling_log(case):
    """postProcessing/coupling.csv written by spoutFoam, as a list of dicts.

    A restarted run appends from its start time, which may lie before rows
    the interrupted run had already written: a row at or before the time of
    the rows above it replaces them (the run continued from there)."""
    rows = []
    with open(os.path.join(case, 'postProcessing', 'coupling.csv')) as f:
        for row in csv.DictReader(f):
            row = {k: float(v) for k, v in row.items()}
            while rows and not earlier(rows[-1]['time [s]'], row['time [s]']):
                rows.pop()
            rows.append(row)
    return rows


# --- VTK XML files (.vtp, .vts) ------------------------------------------------
# spoutFoam writes binary appended data: the XML header, then after
# <AppendedData encoding="raw"> and a '_' the arrays, each at its `offset`.
# An array is [byte count][bytes] uncompressed, or with a compressor
# [blocks][block size][last block size][compressed size of each block] and
# the zlib streams.  The header integers are `header_type` (UInt32 unless
# said).  Inline ASCII arrays (spoutlab.mixing adds those) are read as well.
# Standard library only: several case scripts run without numpy.

VTK_TYPES = {'Int8': 'b', 'UInt8': 'B', 'Int16': 'h', 'UInt16': 'H', 'Int32': 'i',
             'UInt32': 'I', 'Int64': 'q', 'UInt64': 'Q', 'Float32': 'f', 'Float64': 'd'}


class VtkXmlFile:
    """The arrays of one VTK XML file, as flat lists (components interleaved)."""

    def __init__(self, path):
        self.path = path
        with open(path, 'rb') as f:
            data = f.read()
        start = data.find(b'<AppendedData')
        self.appended = None
        if start >= 0:
            tag = re.compile(rb'<AppendedData\s+encoding="(\w+)"\s*>\s*_').match(data, start)
            if not tag or tag.group(1) != b'raw':
                raise ValueError('%s: <AppendedData>: expected encoding="raw" followed by "_"' % path)
            self.appended = memoryview(data)[tag.end():]
            data = data[:start] + b'</VTKFile>'
        try:
            self.root = ET.fromstring(data)
        except ET.ParseError as e:
            raise ValueError('%s: not a VTK XML file (%s)' % (path, e))
        a = self.root.attrib
        self.order = '>' if a.get('byte_order') == 'BigEndian' else '<'
        self.header = VTK_TYPES[a.get('header_type', 'UInt32')]
        self.compressor = a.get('compressor')
        if self.compressor not in (None, 'vtkZLibDataCompressor'):
            raise ValueError('%s: compressor %s: expected vtkZLibDataCompressor or none'
                             % (path, self.compressor))

    def points(self):
        """[(x, y, z)] of the <Points> array."""
        element = self.root.find('.//Points/DataArray')
        if element is None:
            raise ValueError('%s: no <Points> array' % self.path)
        v = self.values(element)
        return list(zip(v[0::3], v[1::3], v[2::3]))

    def array(self, name):
        for element in self.root.iter('DataArray'):
            if element.get('Name') == name:
                return self.values(element)
        raise KeyError('%s: no array named %s' % (self.path, name))

    def values(self, element):
        name, kind, form = element.get('Name'), element.get('type'), element.get('format')
        if kind not in VTK_TYPES:
            raise ValueError('%s: array %s: type %s: expected a numeric VTK type'
                             % (self.path, name, kind))
        if form == 'ascii':
            cast = float if kind.startswith('Float') else int
            return [cast(x) for x in (element.text or '').split()]
        if form == 'appended' and self.appended is not None:
            raw = self.appended_bytes(int(element.get('offset')))
            code = VTK_TYPES[kind]
            return list(struct.unpack('%s%d%s' % (self.order, len(raw) // struct.calcsize(code), code),
                                      raw))
        raise ValueError('%s: array %s: format %s: expected ascii or raw appended'
                         % (self.path, name, form))

    def appended_bytes(self, offset):
        word = struct.calcsize(self.header)
        def ints(at, n):
            return struct.unpack_from('%s%d%s' % (self.order, n, self.header), self.appended, at)
        if self.compressor is None:
            size = ints(offset, 1)[0]
            return bytes(self.appended[offset + word:offset + word + size])
        blocks = ints(offset, 1)[0]
        at = offset + (3 + blocks) * word
        out = []
        for size in ints(offset + 3 * word, blocks):
            out.append(zlib.decompress(self.appended[at:at + size]))
            at += size
        return b''.join(out)


def particle_files(case='.'):
    """[(time, path)] of a case's particle files, particles/particles_<time>.vtp,
    by time (empty without any): the one list of them every reader takes."""
    folder = os.path.join(case, 'particles')
    out = []
    if os.path.isdir(folder):
        for f in os.listdir(folder):
            m = re.match(r'^particles_(.+)\.vtp$', f)
            if m:
                try:
                    out.append((float(m.group(1)), os.path.join(folder, f)))
                except ValueError:
                    pass
    return sorted(out)


def time_name(path):
    """The time of a particle file as its name writes it: '0.0501' of
    particles/particles_0.0501.vtp."""
    return os.path.basename(path)[len('particles_'):-len('.vtp')]


def read_vtp_points(path):
    """Particle positions from a spoutFoam .vtp file, as [(x, y, z)]."""
    return VtkXmlFile(path).points()


def read_vtp_array(path, name):
    """One point array of a .vtp file as a flat list (components interleaved)."""
    return VtkXmlFile(path).array(name)


class Plot:
    """What became of a picture: true if drawn; str() is its name, or its
    name and why it was not drawn, as a summary lists it."""

    def __init__(self, png, why=None):
        self.png, self.why = png, why

    def __bool__(self):
        return self.why is None

    def __str__(self):
        return self.png if self.why is None else '%s not drawn (%s)' % (self.png, self.why)


def not_drawn(png, why):
    """A picture left out (why: one line): said now, and a Plot that says so."""
    print('plot %s not drawn: %s' % (png, why))
    return Plot(png, why)


def plots_text(plots):
    """The pictures as a summary line lists them: the drawn ones, then each
    missing one with why ('none' without any)."""
    drawn = [str(p) for p in plots if p]
    missing = [str(p) for p in plots if not p]
    return '; '.join([' '.join(drawn)] * bool(drawn) + missing) or 'none'


def plot(png, script, size=(900, 600)):
    """Run a gnuplot script that draws into png (pngcairo, or png if absent).
    If gnuplot cannot draw it (e.g. no finite point), say so in one line and
    go on: the data files are written either way.  A Plot: true if drawn,
    else carrying gnuplot's last line, for the summary to name."""
    terminal = 'set terminal pngcairo size %d,%d font "Sans,11"\n' % size
    full = terminal + 'set output "%s"\n' % png + script
    result = subprocess.run(['gnuplot'], input=full, text=True,
                            capture_output=True)
    if result.returncode != 0 or not os.path.isfile(png):
        full = 'set terminal png size %d,%d\nset output "%s"\n' % (size + (png,)) + script
        result = subprocess.run(['gnuplot'], input=full, text=True, capture_output=True)
    if result.returncode != 0:
        if os.path.isfile(png):
            os.remove(png)               # gnuplot leaves an empty file behind
        why = [line.strip() for line in result.stderr.splitlines() if line.strip()]
        return not_drawn(png, 'gnuplot: %s' % (why[-1] if why else 'failed'))
    return Plot(png)


class Checks:
    """Collects (name, value, reference, tolerance) checks, prints a table,
    writes results.txt and gives the exit status."""

    def __init__(self, title):
        self.title = title
        self.rows = []
        self.notes = []

    def relative(self, name, value, reference, tolerance, unit=''):
        error = abs(value - reference) / abs(reference)
        self.rows.append((name, value, reference, error, tolerance, unit))
        return error <= tolerance

    def smaller(self, name, relative_error, tolerance):
        """A relative error measured directly (no value/reference pair)."""
        self.rows.append((name, relative_error, 0.0, relative_error, tolerance, ''))
        return relative_error <= tolerance

    def absolute(self, name, value, reference, tolerance, unit):
        """A difference in the quantity's own unit, |value - reference| <= tolerance."""
        error = abs(value - reference)
        self.rows.append((name, value, reference, error, tolerance, unit, 'absolute'))
        return error <= tolerance

    def note(self, text):
        self.notes.append(text)

    def report(self, path='results.txt'):
        lines = [self.title, '']
        lines.append('%-44s %12s %12s %9s %9s  %s' %
                     ('quantity', 'SpoutLab', 'reference', 'error', 'limit', 'result'))
        ok = True
        for name, value, reference, error, tolerance, unit, *absolute in self.rows:
            passed = error <= tolerance
            ok = ok and passed
            label = name + (' [%s]' % unit if unit else '')
            if absolute:
                limits = '%9.3g %9.3g' % (error, tolerance)
            else:
                limits = '%8.2f%% %8.1f%%' % (100 * error, 100 * tolerance)
            lines.append('%-44s %12.5g %12.5g %s  %s' %
                         (label, value, reference, limits, 'PASS' if passed else 'FAIL'))
        if self.notes:
            lines.append('')
            lines.extend(self.notes)
        text = '\n'.join(lines) + '\n'
        sys.stdout.write(text)
        with open(path, 'w') as f:
            f.write(text)
        return 0 if ok else 1


def solve_quadratic_positive(a, b, c):
    """Positive root of a x^2 + b x + c = 0 (a > 0, c < 0)."""
    return (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a)


def moving_average(times, values, window):
    """Trailing average over `window` seconds at each sample."""
    out, start, total = [], 0, 0.0
    for i, (t, v) in enumerate(zip(times, values)):
        total += v
        while times[start] < t - window + 1e-12:
            total -= values[start]
            start += 1
        out.append(total / (i - start + 1))
    return out
