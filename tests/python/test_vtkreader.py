#!/usr/bin/python3
"""spoutlab.casefiles' VTK XML reader on files VTK wrote (tests/vtk/
writeParticleSample): the values against the sample's formulas, written out
again here from tests/vtk/ParticleSample.hpp, in spoutFoam's layout (zlib,
64-bit headers) and in VTK's plain one (no compression, 32-bit headers); and
mixing's labelled copy of a binary file.

usage: test_vtkreader.py SAMPLE_DIR"""
import math
import os
import shutil
import struct
import sys
import tempfile
import unittest

from spoutlab import mixing
from spoutlab import casefiles as sc

COUNT = 5000


def position(i):
    return (-0.2 + 8e-5 * i, 0.01 + 1e-6 * i, 0.3 * math.sin(i))


def velocity(i):
    return (math.cos(i), math.sin(i), 0.1 * i / COUNT)


def fluid_force(i):
    return (1e-4 * math.sin(0.5 * i), -2e-5, 3e-4 * math.cos(0.5 * i))


def as_float(x):
    """x rounded to single precision, as the file stores fields"""
    return struct.unpack('f', struct.pack('f', x))[0]


class Reader(unittest.TestCase):
    sample = None

    def check(self, path):
        points = sc.read_vtp_points(path)
        self.assertEqual(points, [position(i) for i in range(COUNT)])
        self.assertEqual(sc.read_vtp_array(path, 'id'), [7 + 3 * i for i in range(COUNT)])
        self.assertEqual(sc.read_vtp_array(path, 'radius'),
                         [0.004 + 1e-7 * (i % 5) for i in range(COUNT)])
        self.assertEqual(sc.read_vtp_array(path, 'velocity'),
                         [as_float(c) for i in range(COUNT) for c in velocity(i)])
        self.assertEqual(sc.read_vtp_array(path, 'fluidForce'),
                         [as_float(c) for i in range(COUNT) for c in fluid_force(i)])
        self.assertEqual(sc.read_vtp_array(path, 'dragForce'), [0.0] * (3 * COUNT))
        self.assertEqual(sc.read_vtp_array(path, 'temperature'),
                         [as_float(293.15 + 60.0 * i / COUNT) for i in range(COUNT)])
        self.assertEqual(sc.read_vtp_array(path, 'TimeValue'), [0.5])

    def test_compressed(self):
        self.check(os.path.join(self.sample, 'particles_0.5.vtp'))

    def test_plain(self):
        self.check(os.path.join(self.sample, 'plain.vtp'))

    def test_missing_array_named(self):
        path = os.path.join(self.sample, 'particles_0.5.vtp')
        with self.assertRaisesRegex(KeyError, 'particles_0.5.vtp: no array named heatFlux'):
            sc.read_vtp_array(path, 'heatFlux')

    def test_labelled_copy(self):
        """mixing adds its labels as ASCII arrays to a binary file"""
        folder = tempfile.mkdtemp()
        try:
            source = os.path.join(self.sample, 'particles_0.5.vtp')
            target = os.path.join(folder, 'particles_0.5.vtp')
            ids = sc.read_vtp_array(source, 'id')
            labels = {i: int(position(n)[0] < 0) for n, i in enumerate(ids) if n % 2}
            mixing.write_labelled(source, target, ids, {'left-right': labels})
            self.assertEqual(sc.read_vtp_array(target, 'label_left-right'),
                             [labels.get(i, -1) for i in ids])
            self.assertEqual(sc.read_vtp_points(target), sc.read_vtp_points(source))
            self.assertEqual(sc.read_vtp_array(target, 'velocity'),
                             sc.read_vtp_array(source, 'velocity'))
        finally:
            shutil.rmtree(folder)


if __name__ == '__main__':
    Reader.sample = sys.argv.pop(1)
    unittest.main()
