#!/usr/bin/python3
"""Stored-output regression: a case test's key numbers against committed
references.

Each reference file (tests/regression/<case test>.json) lists a few numbers
of one case test's run: where each is read (a file of the run directory the
case test left in the build tree, and how), its reference value, its
tolerance and why that tolerance.  Nothing is simulated here: the numbers
come from what the case and its evaluate script already wrote.

    check_outputs.py REFERENCE RUN_DIR           compare, one line per number
    check_outputs.py --update REFERENCE RUN_DIR  rewrite the values from RUN_DIR
    check_outputs.py --build BUILD [--update] [NAME ...]
        every reference (or those named, 'packedBed', 'lumpedHeating.Gunn')
        against BUILD/tests/cases/<NAME>

Exit status 1 on drift (or a number that cannot be read), 2 on a bad
reference file.  --update keeps every number's source, tolerance and note
and writes only the values, so the review diff shows exactly what moved.

How a number is read ("from" of each entry):
  {"csv": FILE, "column": NAME, "row": "last" | "first" | INDEX}
  {"csv": FILE, "column": NAME, "at": {"column": NAME, "value": X}}
      the row whose column is nearest X (within 1e-9 of it, relative)
  {"csv": FILE, "column": NAME, "reduce": "max" | "min" | "mean",
   "where": {"column": NAME, "min": A, "max": B}}   (where: optional)
  {"json": FILE, "key": "a.b"}
  {"text": FILE, "pattern": REGEX}   the first match's group 1
Tolerances: {"relative": R} (|got - ref| <= R |ref|) or {"absolute": A}.
"""
import argparse
import csv
import functools
import glob
import json
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


class BadReference(Exception):
    """A reference file that does not say what to read or how to compare."""


class Unreadable(Exception):
    """A number that the run's files do not hold."""


@functools.lru_cache(maxsize=None)
def read_csv(path):
    """(header, rows) of a CSV file, read once per run of this script."""
    with open(path, newline='') as f:
        rows = list(csv.reader(f))
    if not rows:
        raise Unreadable('%s: empty' % path)
    return rows[0], rows[1:]


def column(header, name, path):
    if name not in header:
        raise Unreadable('%s: no column "%s"' % (path, name))
    return header.index(name)


def number(text, path, name):
    try:
        return float(text)
    except ValueError:
        raise Unreadable('%s: "%s" is not a number in column "%s"' % (path, text, name))


def from_csv(source, path):
    header, rows = read_csv(path)
    if not rows:
        raise Unreadable('%s: no rows' % path)
    col = column(header, source['column'], path)
    if 'at' in source:
        at = source['at']
        key = column(header, at['column'], path)
        target = float(at['value'])
        best = min(rows, key=lambda r: abs(number(r[key], path, at['column']) - target))
        found = number(best[key], path, at['column'])
        if abs(found - target) > 1e-9 * max(1.0, abs(target)):
            raise Unreadable('%s: no row with "%s" = %g (nearest %g)'
                             % (path, at['column'], target, found))
        return number(best[col], path, source['column'])
    if 'reduce' in source:
        where = source.get('where')
        if where:
            key = column(header, where['column'], path)
            low = float(where.get('min', -math.inf))
            high = float(where.get('max', math.inf))
            rows = [r for r in rows if low <= number(r[key], path, where['column']) <= high]
        values = [number(r[col], path, source['column']) for r in rows if r[col] != '']
        if not values:
            raise Unreadable('%s: no rows selected for "%s"' % (path, source['column']))
        how = source['reduce']
        if how == 'max':
            return max(values)
        if how == 'min':
            return min(values)
        if how == 'mean':
            return sum(values) / len(values)
        raise BadReference('reduce "%s": expected max, min or mean' % how)
    row = source.get('row', 'last')
    index = {'last': -1, 'first': 0}.get(row, row)
    if not isinstance(index, int):
        raise BadReference('row "%s": expected last, first or a row index' % row)
    try:
        return number(rows[index][col], path, source['column'])
    except IndexError:
        raise Unreadable('%s: no row %d' % (path, index))


def from_json(source, path):
    with open(path) as f:
        value = json.load(f)
    for part in source['key'].split('.'):
        if not isinstance(value, dict) or part not in value:
            raise Unreadable('%s: no key "%s"' % (path, source['key']))
        value = value[part]
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        raise Unreadable('%s: "%s" is not a number' % (path, source['key']))
    return float(value)


def from_text(source, path):
    with open(path) as f:
        match = re.search(source['pattern'], f.read(), re.MULTILINE)
    if not match:
        raise Unreadable('%s: no match for /%s/' % (path, source['pattern']))
    return number(match.group(1), path, source['pattern'])


READERS = {'csv': from_csv, 'json': from_json, 'text': from_text}


def read_number(entry, run_dir):
    source = entry.get('from')
    kinds = [k for k in READERS if isinstance(source, dict) and k in source]
    if len(kinds) != 1:
        raise BadReference('"%s": "from" must hold one of %s'
                           % (entry.get('name'), ', '.join(sorted(READERS))))
    path = os.path.join(run_dir, source[kinds[0]])
    if not os.path.isfile(path):
        raise Unreadable('%s: missing (has the case test run?)' % path)
    try:
        return READERS[kinds[0]](source, path)
    except KeyError as missing:
        raise BadReference('"%s": "from" lacks %s' % (entry.get('name'), missing))


def within(entry, got):
    """(ok, tolerance as text) of one number against its reference."""
    tolerance = entry.get('tolerance', {})
    ref = entry.get('value')
    if len(tolerance) != 1 or not set(tolerance) <= {'relative', 'absolute'}:
        raise BadReference('"%s": tolerance must be {"relative": R} or {"absolute": A}'
                           % entry.get('name'))
    if not entry.get('why'):
        raise BadReference('"%s": no "why" for its tolerance' % entry.get('name'))
    if ref is None:
        return False, 'no reference'
    if 'relative' in tolerance:
        limit = tolerance['relative'] * abs(ref)
        text = 'rel %g' % tolerance['relative']
    else:
        limit = tolerance['absolute']
        text = 'abs %g' % limit
    return math.isfinite(got) and abs(got - ref) <= limit, text


def load(reference):
    try:
        with open(reference) as f:
            data = json.load(f)
    except (OSError, ValueError) as error:
        raise BadReference('%s: %s' % (reference, error))
    if not isinstance(data.get('numbers'), list) or not data['numbers']:
        raise BadReference('%s: "numbers": expected a list of numbers to check' % reference)
    return data


def write(reference, data):
    """JSON with one line per field of a number, so that a review diff of an
    update shows one changed line per value that moved."""
    def one(value):
        return json.dumps(value, ensure_ascii=False)
    lines = ['{']
    for key, value in data.items():
        if key != 'numbers':
            lines.append('  %s: %s,' % (one(key), one(value)))
    lines.append('  "numbers": [')
    for i, entry in enumerate(data['numbers']):
        fields = ['    %s: %s' % (one(k), one(v)) for k, v in entry.items()]
        lines.append('   {\n' + ',\n'.join(fields) + '\n   }'
                     + (',' if i + 1 < len(data['numbers']) else ''))
    lines.append('  ]')
    lines.append('}')
    text = '\n'.join(lines) + '\n'
    with open(reference, 'w') as f:
        f.write(text)


def check(reference, run_dir, update=False, out=sys.stdout):
    """Compare (or update) one reference file; returns the exit status."""
    data = load(reference)
    name = os.path.splitext(os.path.basename(reference))[0]
    out.write('%s (%s)\n' % (data.get('test', name), run_dir))
    out.write('  %-56s %14s %14s %12s  %s\n' % ('number', 'reference', 'got', 'tolerance', ''))
    status = 0
    values = []
    for entry in data['numbers']:
        try:
            got = read_number(entry, run_dir)
            ok, tol = within(entry, got)
        except Unreadable as error:
            out.write('  %-56s %s\n' % (entry.get('name'), error))
            status = 1
            continue
        except BadReference as error:
            raise BadReference('%s: %s' % (reference, error))
        values.append((entry, got))
        ref = entry.get('value')
        verdict = 'ok' if ok else ('updated' if update else 'DRIFT')
        out.write('  %-56s %14s %14.8g %12s  %s\n'
                  % (entry['name'], 'none' if ref is None else '%.8g' % ref, got, tol, verdict))
        if not ok and not update:
            status = 1
    if update:
        if status:
            out.write('  not updated: a number could not be read\n')
            return status
        for entry, got in values:
            entry['value'] = got
        write(reference, data)
        out.write('  %s rewritten\n' % os.path.relpath(reference))
    return status


class Parser(argparse.ArgumentParser):
    def error(self, message):
        """A bad command line is one line."""
        self.exit(2, '%s: %s (see --help)\n' % (self.prog, message))


def main(argv=None):
    parser = Parser(
        prog='check_outputs.py', description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--update', action='store_true',
                        help='rewrite the reference values from the run')
    parser.add_argument('--build', metavar='BUILD',
                        help='check NAMEs (default: every reference) against BUILD/tests/cases/NAME')
    parser.add_argument('items', nargs='*', metavar='ARG',
                        help='REFERENCE RUN_DIR, or NAMEs with --build')
    args = parser.parse_args(argv)
    if args.build:
        names = args.items or sorted(os.path.splitext(os.path.basename(p))[0]
                                     for p in glob.glob(os.path.join(HERE, '*.json')))
        pairs = [(os.path.join(HERE, n + '.json'),
                  os.path.join(args.build, 'tests', 'cases', n)) for n in names]
    elif len(args.items) == 2:
        pairs = [tuple(args.items)]
    else:
        parser.error('give REFERENCE RUN_DIR, or --build BUILD [NAME ...]')
    status = 0
    for reference, run_dir in pairs:
        try:
            status = max(status, check(reference, run_dir, args.update))
        except BadReference as error:
            print('check_outputs.py: %s' % error, file=sys.stderr)
            return 2
    return status


if __name__ == '__main__':
    sys.exit(main())
