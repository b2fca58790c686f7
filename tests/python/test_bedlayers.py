"""A column's layers from the particles (spoutlab.bedlayers): exact sphere
slices, and the divided model's pieces as the solver places them."""
import math
import unittest

import numpy as np

from spoutlab import bedlayers as bl

FACES = 0.01 * np.arange(6)
LOWER, UPPER = [0.0, 0.0, 0.0], [0.12, 0.04, 0.05]


class SphereSlice(unittest.TestCase):
    def test_whole_and_half(self):
        r = np.array([0.004])
        self.assertAlmostEqual(float(bl.sphere_slice(np.array([0.0]), r, -1, 1)[0]),
                               4 / 3 * math.pi * 0.004 ** 3, places=18)
        self.assertAlmostEqual(float(bl.sphere_slice(np.array([0.0]), r, 0, 1)[0]),
                               2 / 3 * math.pi * 0.004 ** 3, places=18)


class DividedPieces(unittest.TestCase):
    def test_pattern(self):
        offsets = bl.divided_offsets()
        self.assertEqual(offsets.shape, (30, 3))
        # equal-volume pieces of a ball: their centroids average to its centre
        self.assertLess(np.max(np.abs(offsets.mean(axis=0))), 1e-15)
        self.assertTrue(np.all(np.linalg.norm(offsets, axis=1) < 1))
        # a rotation keeps each centroid's distance from the centre: the
        # polar cap of the outer shell, 3/4 (1 - r_in^4)/(1 - r_in^3) x
        # (1 + z_cap)/2 with r_in^3 = 2/3 and z_cap = 1 - 2/10
        r_in = (2 / 3) ** (1 / 3)
        cap = 0.75 * (1 - r_in ** 4) / (1 - r_in ** 3) * (1 + 0.8) / 2
        self.assertAlmostEqual(np.max(np.linalg.norm(offsets, axis=1)), cap, places=14)

    def test_volume_kept_and_inside_whole(self):
        rng = np.random.default_rng(3)
        points = np.column_stack([rng.uniform(0, 0.12, 200), rng.uniform(0, 0.04, 200),
                                  rng.uniform(0.004, 0.046, 200)])
        r = np.full(200, 0.004)
        share = bl.divided_share(points, r, FACES, LOWER, UPPER)
        self.assertLess(np.max(np.abs(share.sum(axis=0) / (4 / 3 * math.pi * r ** 3) - 1)), 1e-14)
        inside = bl.divided_share(np.array([[0.06, 0.02, 0.015]]), r[:1], FACES, LOWER, UPPER)
        self.assertEqual(list(inside[:, 0] > 0), [False, True, False, False, False])

    def test_face_cuts_as_the_caps(self):
        # centred on a face: half and half; anywhere: within 0.07 of the caps
        r = np.array([0.004])
        volume = 4 / 3 * math.pi * 0.004 ** 3
        on_face = bl.divided_share(np.array([[0.06, 0.02, 0.02]]), r, FACES, LOWER, UPPER)
        self.assertAlmostEqual(on_face[1, 0] / volume, 0.5, places=14)
        for z in np.linspace(0.0165, 0.0235, 57):
            share = bl.divided_share(np.array([[0.06, 0.02, z]]), r, FACES, LOWER, UPPER)
            exact = bl.sphere_slice(np.array([z]), r, 0.01, 0.02)[0]
            self.assertLess(abs(share[1, 0] - exact) / volume, 0.07, msg='z = %g' % z)

    def test_pieces_beyond_a_wall_stay_in_the_centre_layer(self):
        r = np.array([0.004])
        # centre 1 mm from the wall x = 0 and 1 mm below a face: the pieces
        # beyond the wall count to the centre's layer
        share = bl.divided_share(np.array([[0.001, 0.02, 0.019]]), r, FACES, LOWER, UPPER)
        pieces = 0.004 * bl.divided_offsets() + [0.001, 0.02, 0.019]
        above = np.sum((pieces[:, 2] >= 0.02) & (pieces[:, 0] >= 0))
        volume = 4 / 3 * math.pi * 0.004 ** 3
        self.assertAlmostEqual(share[2, 0] / volume, above / 30, places=14)
        self.assertAlmostEqual(share[1, 0] / volume, 1 - above / 30, places=14)


if __name__ == '__main__':
    unittest.main()
