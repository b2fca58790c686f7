"""Render spoutFoam's particles as spheres of their own radius, coloured by
any point array, to a PNG -- a picture without opening the ParaView GUI.

  pvpython etc/paraview/particles.py CASE/particles/particles.pvd \\
      [--array velocity] [--component Magnitude|X|Y|Z] [--time last|T] \\
      [--size 1200x900] [-o particles.png]

A single .vtp works as well as the .pvd.  The camera looks along +y (through
the bed's depth) at the whole bed.  Off screen: `pvpython --force-offscreen-
rendering`, or under xvfb-run on a machine without a display.
"""
import argparse

from paraview import simple


def arguments():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument('file', help='particles.pvd or one particles_<time>.vtp')
    p.add_argument('--array', default='velocity', help='point array to colour by (default velocity)')
    p.add_argument('--component', default='Magnitude',
                   help='Magnitude or X, Y, Z for a vector array (default Magnitude)')
    p.add_argument('--time', default='last', help="'last' (default) or a time in s")
    p.add_argument('--size', default='1200x900', help='image size WxH in pixels')
    p.add_argument('-o', '--output', default='particles.png')
    return p.parse_args()


def spheres(source, view, array, component):
    """Point Gaussian with the sphere shader, each point scaled by its radius"""
    display = simple.Show(source, view)
    display.SetRepresentationType('Point Gaussian')
    display.ShaderPreset = 'Sphere'
    display.ScaleByArray = 1
    display.SetScaleArray = ['POINTS', 'radius']
    display.UseScaleFunction = 0
    display.GaussianRadius = 1.0
    names = source.PointData.keys()
    if array not in names:
        raise SystemExit('particles.py: %s: no point array %s (has %s)'
                         % (source.FileName, array, ', '.join(names)))
    if source.PointData[array].GetNumberOfComponents() > 1:
        simple.ColorBy(display, ('POINTS', array, component))
    else:
        simple.ColorBy(display, ('POINTS', array))
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)
    return display


def main():
    args = arguments()
    reader = simple.OpenDataFile(args.file)
    if reader is None:
        raise SystemExit('particles.py: %s: ParaView cannot open it' % args.file)
    times = list(reader.TimestepValues) if hasattr(reader, 'TimestepValues') else []
    view = simple.GetActiveViewOrCreate('RenderView')
    width, height = (int(v) for v in args.size.lower().split('x'))
    view.ViewSize = [width, height]
    if times:
        view.ViewTime = times[-1] if args.time == 'last' else float(args.time)
    reader.UpdatePipeline(view.ViewTime)
    spheres(reader, view, args.array, args.component)
    view.CameraPosition = [0.0, -2.0, 0.3]
    view.CameraFocalPoint = [0.0, 0.0, 0.3]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera()
    simple.SaveScreenshot(args.output, view, ImageResolution=[width, height])
    print('particles.py: wrote %s (%s at t = %g s)' % (args.output, args.array, view.ViewTime))


if __name__ == '__main__':
    main()
