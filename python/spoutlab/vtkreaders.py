"""SpoutLab's outputs through VTK's own readers -- the code ParaView opens
them with -- where every message a reader gives is an error: ParaView shows
the same messages in its Output Messages window, so a file that opens here
in silence opens there without one.  VTK's Python (python3-vtk9, which
libvtk9-dev brings for the build); no ParaView Python (pvpython) needed.

  read_xml(path)            one .vtp / .vts / .vtu through VTK's XML reader
  read_collection(pvd)      a .pvd collection: [(time, path)] in time order
  OpenFoamCase(foam)        a case's .foam through vtkOpenFOAMReader, every
                            time, every cell array, every patch

Each raises ReadError, one line naming the file and what the reader said.
"""
import os
import re
import xml.etree.ElementTree as ET

from vtkmodules.vtkCommonCore import vtkLogger, vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkIOGeometry import vtkOpenFOAMReader
from vtkmodules.vtkIOXML import (vtkXMLPolyDataReader, vtkXMLStructuredGridReader,
                                 vtkXMLUnstructuredGridReader)

XML_READERS = {'.vtp': vtkXMLPolyDataReader, '.vts': vtkXMLStructuredGridReader,
               '.vtu': vtkXMLUnstructuredGridReader}


class ReadError(Exception):
    """A file VTK cannot read, or reads only with a message."""


class Messages:
    """Every text VTK's objects give (errors, warnings) from now on, kept
    instead of printed; new() returns what came since the last call."""

    def __init__(self):
        self.window = vtkStringOutputWindow()
        vtkOutputWindow.SetInstance(self.window)
        # the logger would print each message to stderr a second time
        vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
        self.seen = 0

    def new(self):
        text = self.window.GetOutput()
        fresh, self.seen = text[self.seen:], len(text)
        return fresh


_messages = None


def messages():
    global _messages
    if _messages is None:
        _messages = Messages()
    return _messages


def summary(text):
    """The first message of VTK's output as one line, without its source
    location and object address: 'vtkXMLPolyDataReader: Error reading ...'."""
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    lines = [line for line in lines if not re.match(r'(ERROR|Warning|Generic Warning): In ', line)]
    first = lines[0] if lines else text.strip()
    return re.sub(r' \(0x[0-9a-f]+\)', '', first)


def check_silent(path, reader=None):
    """ReadError if VTK said anything (or the reader set an error code)
    since the last check."""
    said = messages().new()
    if said:
        raise ReadError('%s: %s' % (path, summary(said)))
    if reader is not None and reader.GetErrorCode():
        raise ReadError('%s: VTK reader error code %d' % (path, reader.GetErrorCode()))


def read_xml(path):
    """The data set of one VTK XML file (its reader chosen by the extension)."""
    extension = os.path.splitext(path)[1]
    if extension not in XML_READERS:
        raise ReadError('%s: not a VTK XML data file (expected %s)'
                        % (path, ', '.join(sorted(XML_READERS))))
    if not os.path.isfile(path):
        raise ReadError('%s: no such file' % path)
    messages().new()
    reader = XML_READERS[extension]()
    reader.SetFileName(path)
    reader.Update()
    check_silent(path, reader)
    return reader.GetOutput()


def read_collection(pvd):
    """[(time, path)] of a ParaView .pvd collection in time order, each file
    there, as ParaView's PVD reader lists them."""
    try:
        root = ET.parse(pvd).getroot()
    except (OSError, ET.ParseError) as e:
        raise ReadError('%s: not a readable .pvd collection (%s)' % (pvd, e))
    if root.tag != 'VTKFile' or root.get('type') != 'Collection' or root.find('Collection') is None:
        raise ReadError('%s: expected <VTKFile type="Collection"> with a <Collection>' % pvd)
    entries = []
    for data_set in root.find('Collection').iter('DataSet'):
        name, step = data_set.get('file'), data_set.get('timestep')
        try:
            time = float(step)
        except (TypeError, ValueError):
            raise ReadError('%s: DataSet %r: expected a numeric timestep, got %r'
                            % (pvd, name, step))
        path = os.path.join(os.path.dirname(pvd), name or '')
        if not name or not os.path.isfile(path):
            raise ReadError('%s: DataSet at t = %g: file %r does not exist' % (pvd, time, name))
        entries.append((time, path))
    if not entries:
        raise ReadError('%s: the collection lists no data sets' % pvd)
    return sorted(entries)


def selections(reader, kind):
    """Names of a vtkOpenFOAMReader selection ('Cell', 'Point', 'Patch', ...)."""
    count = getattr(reader, 'GetNumberOf%sArrays' % kind)()
    return [getattr(reader, 'Get%sArrayName' % kind)(i) for i in range(count)]


class OpenFoamCase:
    """A case's .foam opened as ParaView opens it, with every cell array,
    every patch and the decomposed polyhedra of the default; read(t) is the
    data at one time."""

    def __init__(self, foam):
        self.foam = foam
        if not os.path.isfile(foam):
            raise ReadError('%s: no such file' % foam)
        messages().new()
        self.reader = vtkOpenFOAMReader()
        self.reader.SetFileName(foam)
        self.reader.UpdateInformation()
        check_silent(foam)
        self.reader.EnableAllCellArrays()
        self.reader.EnableAllPointArrays()
        self.reader.EnableAllPatchArrays()
        values = self.reader.GetTimeValues()
        self.times = [values.GetValue(i) for i in range(values.GetNumberOfTuples())] \
            if values else []
        if not self.times:
            raise ReadError('%s: vtkOpenFOAMReader finds no time directory' % foam)

    def cell_arrays(self):
        return selections(self.reader, 'Cell')

    def patches(self):
        return selections(self.reader, 'Patch')

    def read(self, time):
        """The multiblock (internal mesh, boundary) at a time of self.times."""
        self.reader.UpdateTimeStep(time)
        self.reader.Update()
        check_silent('%s at t = %.6g' % (self.foam, time), self.reader)
        return self.reader.GetOutput()
