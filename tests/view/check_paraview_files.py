"""What a run writes for ParaView opens through VTK's own readers (ParaView's
code) without a message, with every array non-empty and finite:

  check_paraview_files.py foam CASE.foam --scratch DIR [--arrays U,p] [--written T,Qs]
      every time of the case (0 included), every cell array, every patch; each
      field file of a time directory is an array there; --arrays at every
      time, --written at every time after the first
  check_paraview_files.py series FILE.pvd --scratch DIR [--arrays radius,velocity]
      every data set of the collection, every .vtp/.vts in their folders listed
      in it, the named point (or cell) arrays in each
  check_paraview_files.py png FILE.pvd OUT.png [particles.py options]
      etc/paraview/particles.py draws it off screen (under xvfb-run without a
      display); the picture has the size asked for and is not blank

foam and series also check that the readers see a broken file: a copy of
one file cut to half its length, and for foam a copy of the initial
temperature with OpenFOAM macros ($T0, as 0/T once had) must be refused.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

TOP = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..')
from spoutlab.vtkreaders import (XML_READERS, OpenFoamCase, ReadError, read_collection,
                                 read_xml)

import numpy  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkDataObjectTreeIterator  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402


class CheckError(Exception):
    pass


def check_arrays(where, data, required=()):
    """Every point and cell array of a data set has one tuple per point or
    cell, at least one, and only finite values; `required` are among them.
    Returns the names."""
    names = set()
    for kind, attributes, count in (('point', data.GetPointData(), data.GetNumberOfPoints()),
                                    ('cell', data.GetCellData(), data.GetNumberOfCells())):
        for i in range(attributes.GetNumberOfArrays()):
            array = attributes.GetArray(i)
            if array is None:      # a string or other abstract array: no values to check
                continue
            name = array.GetName()
            names.add(name)
            if array.GetNumberOfTuples() != count or count == 0:
                raise CheckError('%s: %s array %s: %d tuples for %d %ss'
                                 % (where, kind, name, array.GetNumberOfTuples(), count, kind))
            values = vtk_to_numpy(array)
            if not numpy.isfinite(values).all():
                raise CheckError('%s: %s array %s: %d values not finite'
                                 % (where, kind, name, numpy.size(values)
                                    - numpy.count_nonzero(numpy.isfinite(values))))
    missing = [n for n in required if n not in names]
    if missing:
        raise CheckError('%s: no array %s (has %s)' % (where, ', '.join(missing),
                                                       ', '.join(sorted(names))))
    return names


def leaves(block):
    """(name, data set) of every non-empty leaf of a multiblock."""
    it = vtkDataObjectTreeIterator()
    it.SetDataSet(block)
    it.VisitOnlyLeavesOn()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        data = it.GetCurrentDataObject()
        name = it.GetCurrentMetaData().Get(block.NAME()) if it.HasCurrentMetaData() else '?'
        if data is not None and data.GetNumberOfCells() > 0:
            yield name, data
        it.GoToNextItem()


FIELD_CLASS = re.compile(rb'^\s*class\s+vol\w+Field\s*;', re.M)


def field_files(directory):
    """The volume fields of a time directory (by their FoamFile class)."""
    out = set()
    for name in os.listdir(directory):
        path = os.path.join(directory, name)
        if os.path.isfile(path):
            with open(path, 'rb') as f:
                if FIELD_CLASS.search(f.read(2000)):
                    out.add(name)
    return out


def time_directory(case, time, names):
    """The directory name of a time among a case's time directories."""
    for name in names:
        try:
            if abs(float(name) - time) <= 1e-9 * max(1.0, abs(time)):
                return os.path.join(case, name)
        except ValueError:
            pass
    raise CheckError('%s: no time directory for t = %g' % (case, time))


def check_case(foam, arrays, written):
    """Every time of a case; returns (times, arrays of the internal mesh)."""
    case = os.path.dirname(os.path.abspath(foam))
    reader = OpenFoamCase(foam)
    if 'internalMesh' not in reader.patches():
        raise CheckError('%s: the reader lists no internalMesh' % foam)
    dirs = os.listdir(case)
    seen = set()
    for i, t in enumerate(reader.times):
        data = reader.read(t)
        where = '%s at t = %g' % (foam, t)
        blocks = dict(leaves(data))
        if 'internalMesh' not in blocks:
            raise CheckError('%s: no internal mesh in the output' % where)
        need = list(arrays) + (list(written) if i > 0 else [])
        need += sorted(field_files(time_directory(case, t, dirs)))
        for name, block in blocks.items():
            found = check_arrays('%s, %s' % (where, name), block,
                                 need if name == 'internalMesh' else ())
            if name == 'internalMesh':
                seen |= found
    return reader.times, seen


def check_series(pvd, arrays):
    """Every data set of a collection; every data file in the folders of
    its files is listed (none left out of the series)."""
    series = read_collection(pvd)
    listed = {os.path.abspath(path) for _, path in series}
    for folder in sorted({os.path.dirname(path) for path in listed}):
        for name in sorted(os.listdir(folder)):
            path = os.path.join(folder, name)
            if os.path.splitext(name)[1] in XML_READERS and path not in listed:
                raise CheckError('%s: %s is not in the collection' % (pvd, path))
    points = []
    for t, path in series:
        data = read_xml(path)
        if data.GetNumberOfPoints() == 0:
            raise CheckError('%s: no points' % path)
        check_arrays(path, data, arrays)
        points.append(data.GetNumberOfPoints())
    return series, points


def must_refuse(what, check):
    """The negative control: `check` must raise ReadError."""
    try:
        check()
    except ReadError as e:
        print('  refused as it must be: %s' % e)
        return
    raise CheckError('%s was read without an error: the check would miss a broken file' % what)


def truncated_copy(path, scratch):
    """A copy of a file cut to half its length, in scratch."""
    os.makedirs(scratch, exist_ok=True)
    copy = os.path.join(scratch, 'truncated_' + os.path.basename(path))
    with open(path, 'rb') as f:
        data = f.read()
    with open(copy, 'wb') as f:
        f.write(data[:len(data) // 2])
    return copy


def broken_case(foam, scratch):
    """A copy of a case's mesh and first time with 0/T as it once was
    (#include and $T0) and a second field cut to half its length: the
    reader must refuse each.  Yields (what, .foam)."""
    case = os.path.dirname(os.path.abspath(foam))
    reader = OpenFoamCase(foam)
    first = time_directory(case, reader.times[0], os.listdir(case))
    fields = sorted(field_files(first))
    for kind in ('macro', 'truncated'):
        copy = os.path.join(scratch, kind)
        shutil.rmtree(copy, ignore_errors=True)
        os.makedirs(os.path.join(copy, 'constant'))
        shutil.copytree(os.path.join(case, 'system'), os.path.join(copy, 'system'))
        shutil.copytree(os.path.join(case, 'constant', 'polyMesh'),
                        os.path.join(copy, 'constant', 'polyMesh'))
        shutil.copytree(first, os.path.join(copy, os.path.basename(first)))
        target = os.path.join(copy, os.path.basename(first))
        if kind == 'macro':
            with open(os.path.join(copy, 'constant', 'heatTransfer'), 'w') as f:
                f.write('T0 306.15;\nTin 423.15;\n')
            with open(os.path.join(target, 'T'), 'w') as f:
                f.write('FoamFile { version 2.0; format ascii; class volScalarField; object T; }\n'
                        '#include "$FOAM_CASE/constant/heatTransfer"\n'
                        'dimensions [0 0 0 1 0 0 0];\ninternalField uniform $T0;\n'
                        'boundaryField { ".*" { type fixedValue; value uniform $Tin; } }\n')
            what = 'a 0/T with #include and $T0'
        else:
            name = 'U' if 'U' in fields else fields[0]
            field = os.path.join(target, name)
            shutil.move(truncated_copy(field, copy), field)
            what = 'a time directory with %s cut to half its length' % name
        stub = os.path.join(copy, kind + '.foam')
        open(stub, 'w').close()
        yield what, stub


def foam_command(a):
    times, arrays = check_case(a.file, split(a.arrays), split(a.written))
    print('%s: %d times (%s ... %s s), each with every cell array and patch; arrays %s'
          % (a.file, len(times), '%g' % times[0], '%g' % times[-1], ', '.join(sorted(arrays))))
    for what, stub in broken_case(a.file, a.scratch):
        def read_all(stub=stub):
            reader = OpenFoamCase(stub)
            for t in reader.times:
                reader.read(t)
        must_refuse(what, read_all)


def series_command(a):
    series, points = check_series(a.file, split(a.arrays))
    print('%s: %d files (t = %g ... %g s), %d ... %d points, arrays %s present'
          % (a.file, len(series), series[0][0], series[-1][0], min(points), max(points),
             a.arrays or '(none named)'))
    path = series[-1][1]
    must_refuse('a copy of %s cut to half its length' % os.path.basename(path),
                lambda: read_xml(truncated_copy(path, a.scratch)))


def png_command(a, options):
    script = os.path.join(TOP, 'etc', 'paraview', 'particles.py')
    command = [sys.executable, script, a.file, '-o', a.output, '--size', a.size] + options
    if not os.environ.get('DISPLAY'):
        if not shutil.which('xvfb-run'):
            raise CheckError('no X display and no xvfb-run (Debian: xvfb; etc/setup installs it)')
        command = ['xvfb-run', '-a'] + command
    if os.path.exists(a.output):
        os.remove(a.output)
    run = subprocess.run(command, capture_output=True, text=True)
    if run.returncode != 0 or run.stderr.strip():
        raise CheckError('%s failed (exit %d): %s' % (' '.join(command), run.returncode,
                                                       (run.stderr or run.stdout).strip()))
    print(run.stdout.strip())
    width, height = (int(v) for v in a.size.split('x'))
    reader = vtkPNGReader()
    reader.SetFileName(a.output)
    reader.Update()
    image = reader.GetOutput()
    if image.GetDimensions()[:2] != (width, height):
        raise CheckError('%s: %s pixels, expected %dx%d' % (a.output, image.GetDimensions()[:2],
                                                            width, height))
    # the particles' part of the picture: left of the colour bar (the right
    # 16 %), above the time label (the bottom 8 %); VTK's rows run upwards
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].reshape(height, width, 3)
    pixels = pixels[int(0.08 * height):, :int(0.84 * width)].reshape(-1, 3)
    background = numpy.all(pixels == pixels[0], axis=1)
    drawn = 1 - numpy.count_nonzero(background) / len(pixels)
    colours = len(numpy.unique(pixels[~background], axis=0))
    print('%s: %dx%d, %.1f %% of the particles\' part drawn, %d colours'
          % (a.output, width, height, 100 * drawn, colours))
    # 3000 particles of 8 mm in a 0.5 m wide bed cover several per cent of
    # the picture; shaded spheres coloured by value give hundreds of colours
    if drawn < 0.01 or colours < 500:
        raise CheckError('%s: blank or flat picture (%.2f %% drawn, %d colours)'
                         % (a.output, 100 * drawn, colours))


def split(text):
    return [v for v in (text or '').split(',') if v]


def main(argv):
    p = argparse.ArgumentParser(prog='check_paraview_files.py', description=__doc__.splitlines()[0])
    sub = p.add_subparsers(dest='command', required=True)
    foam = sub.add_parser('foam')
    foam.add_argument('file')
    foam.add_argument('--scratch', required=True, help='directory for the broken copies')
    foam.add_argument('--arrays', help='cell arrays every time must have')
    foam.add_argument('--written', help='cell arrays every time after the first must have')
    series = sub.add_parser('series')
    series.add_argument('file')
    series.add_argument('--scratch', required=True, help='directory for the broken copy')
    series.add_argument('--arrays', help='arrays every data set must have')
    png = sub.add_parser('png')
    png.add_argument('file')
    png.add_argument('output')
    png.add_argument('--size', default='800x600')
    a, rest = p.parse_known_args(argv)
    if rest and a.command != 'png':
        p.error('unrecognized arguments: %s' % ' '.join(rest))
    try:
        if a.command == 'foam':
            foam_command(a)
        elif a.command == 'series':
            series_command(a)
        else:
            png_command(a, rest)
    except (CheckError, ReadError) as e:
        sys.exit('check_paraview_files.py: %s' % e)


if __name__ == '__main__':
    main(sys.argv[1:])
