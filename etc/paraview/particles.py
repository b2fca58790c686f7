"""Render spoutFoam's particles as spheres of their own radius, coloured by
any point array, to a PNG -- a picture without opening the ParaView GUI.

  /usr/bin/python3 etc/paraview/particles.py CASE/particles/particles.pvd \\
      [--array velocity] [--component Magnitude|X|Y|Z] [--time last|T] \\
      [--range MIN,MAX] [--size 1200x900] [-o particles.png]

A single .vtp works as well as the .pvd (postProcessing/mixingParticles/
particles.pvd too: --array label_left-right).  The camera looks along +y
(through the bed's depth) at all the particles.  VTK's Python
(python3-vtk9), off screen; VTK draws through X, so where there is no
display run it under xvfb-run -a.
"""
import argparse
import os
import sys

try:
    from spoutlab import cli  # the one-line bad-option parser
except ModuleNotFoundError as e:
    if e.name != 'spoutlab':
        raise
    sys.exit("particles.py: cannot find SpoutLab's Python package: source its environment "
             "first, '. <SpoutLab directory>/etc/bashrc'")
from spoutlab.vtkreaders import ReadError, read_collection, read_xml  # noqa: E402

from vtkmodules.vtkFiltersSources import vtkSphereSource  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGWriter  # noqa: E402
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction,  # noqa: E402
                                         vtkGlyph3DMapper, vtkRenderer, vtkRenderWindow,
                                         vtkTextActor, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401  (the render window's back end)
import vtkmodules.vtkRenderingFreeType  # noqa: E402,F401  (text of the colour bar)

COMPONENTS = ('Magnitude', 'X', 'Y', 'Z')
# ParaView's default background and its "Cool to Warm" map: Moreland's
# diverging map, end points (59, 76, 192) and (180, 4, 38) of 255
# (K. Moreland, Diverging Color Maps for Scientific Visualization, ISVC 2009)
BACKGROUND = (0.32, 0.34, 0.43)
COOL, WARM = (0.230, 0.299, 0.754), (0.706, 0.016, 0.150)


def numbers(kind, separator, form):
    """An argparse type: two numbers as in `form`."""
    def parse(text):
        try:
            a, b = (kind(v) for v in text.lower().split(separator))
        except ValueError:
            raise argparse.ArgumentTypeError('expected %s, got %r' % (form, text))
        return a, b
    return parse


def arguments(argv):
    p = cli.Parser(prog='particles.py', description=__doc__.splitlines()[0])
    p.add_argument('file', help='particles.pvd or one particles_<time>.vtp')
    p.add_argument('--array', default='velocity', help='point array to colour by (default velocity)')
    p.add_argument('--component', default='Magnitude', choices=COMPONENTS,
                   help='of a vector array (default Magnitude)')
    p.add_argument('--time', default='last', help="'last' (default) or a time in s")
    p.add_argument('--range', type=numbers(float, ',', 'MIN,MAX'),
                   help='colour range MIN,MAX (default: the data range)')
    p.add_argument('--size', default=(1200, 900), type=numbers(int, 'x', 'WxH'),
                   help='image size WxH in pixels (default 1200x900)')
    p.add_argument('-o', '--output', default='particles.png')
    return p.parse_args(argv)


def pick_file(path, when):
    """(time or None, the .vtp) of a .pvd at 'last' or the written time
    nearest to `when`, or a single .vtp."""
    if not path.endswith('.pvd'):
        return None, path
    series = read_collection(path)
    if when == 'last':
        return series[-1]
    try:
        t = float(when)
    except ValueError:
        raise ReadError("%s: --time expected 'last' or a time in s, got %r" % (path, when))
    return min(series, key=lambda entry: abs(entry[0] - t))


def colour_map(data, name, component, limits):
    """(lookup table, range, title) of a point array."""
    array = data.GetPointData().GetArray(name)
    if array is None:
        names = [data.GetPointData().GetArrayName(i)
                 for i in range(data.GetPointData().GetNumberOfArrays())]
        raise ReadError('no point array %r (has %s)' % (name, ', '.join(names)))
    vector = array.GetNumberOfComponents() > 1
    index = -1 if not vector or component == 'Magnitude' else COMPONENTS.index(component) - 1
    lo, hi = limits if limits else array.GetRange(index)
    if hi <= lo:
        hi = lo + 1.0           # one value: still a colour, not a division by zero
    table = vtkColorTransferFunction()
    table.SetColorSpaceToDiverging()
    table.AddRGBPoint(lo, *COOL)
    table.AddRGBPoint(hi, *WARM)
    if vector and index < 0:
        table.SetVectorModeToMagnitude()
    elif vector:
        table.SetVectorModeToComponent()
        table.SetVectorComponent(index)
    title = name + (' (%s)' % component if vector else '')
    return table, (lo, hi), title


def spheres(data, name, table, limits):
    """Each point a sphere of its `radius`, coloured through the table."""
    sphere = vtkSphereSource()
    sphere.SetRadius(1.0)
    sphere.SetThetaResolution(16)
    sphere.SetPhiResolution(12)
    mapper = vtkGlyph3DMapper()
    mapper.SetInputData(data)
    mapper.SetSourceConnection(sphere.GetOutputPort())
    mapper.SetScaleArray('radius')
    mapper.SetScaleModeToScaleByMagnitude()
    mapper.SetScaleFactor(1.0)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray(name)
    mapper.SetLookupTable(table)
    mapper.SetScalarRange(*limits)
    mapper.ScalarVisibilityOn()
    actor = vtkActor()
    actor.SetMapper(mapper)
    return actor


def render(data, args, time):
    width, height = args.size
    if data.GetPointData().GetArray('radius') is None:
        raise ReadError('no point array radius: not a spoutFoam particle file')
    table, limits, title = colour_map(data, args.array, args.component, args.range)
    renderer = vtkRenderer()
    renderer.SetBackground(*BACKGROUND)
    renderer.AddActor(spheres(data, args.array, table, limits))
    bar = vtkScalarBarActor()
    bar.SetLookupTable(table)
    bar.SetTitle(title)
    bar.SetNumberOfLabels(5)
    bar.UnconstrainedFontSizeOn()
    bar.GetTitleTextProperty().SetFontSize(max(12, height // 45))
    bar.GetLabelTextProperty().SetFontSize(max(10, height // 55))
    bar.SetVerticalTitleSeparation(max(4, height // 90))
    bar.SetPosition(0.86, 0.1)     # the right 14 %, clear of the particles
    bar.SetWidth(0.1)
    bar.SetHeight(0.8)
    renderer.AddActor2D(bar)
    if time is not None:
        label = vtkTextActor()
        label.SetInput('t = %g s' % time)
        label.GetTextProperty().SetFontSize(max(12, height // 40))
        label.SetPosition(10, 10)
        renderer.AddActor2D(label)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, -1.0, 0.0)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.SetViewUp(0.0, 0.0, 1.0)
    camera.ParallelProjectionOn()
    renderer.ResetCamera()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(width, height)
    window.Render()
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    image.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()
    window.Finalize()


def main(argv=None):
    args = arguments(argv)
    if not os.environ.get('DISPLAY'):
        sys.exit('particles.py: no X display (DISPLAY is not set): run it as '
                 'xvfb-run -a /usr/bin/python3 %s ...' % sys.argv[0])
    try:
        time, path = pick_file(args.file, args.time)
        data = read_xml(path)
    except ReadError as e:
        sys.exit('particles.py: %s' % e)
    try:
        render(data, args, time)
    except ReadError as e:
        sys.exit('particles.py: %s: %s' % (path, e))
    print('particles.py: wrote %s (%s%s, %d particles)'
          % (args.output, args.array, '' if time is None else ' at t = %g s' % time,
             data.GetNumberOfPoints()))


if __name__ == '__main__':
    main()
