"""The evaluate scripts' own heat-transfer references
(spoutlab.heatcorrelations) and the reading of coupling.csv: hand values of the
correlations, the energy bookkeeping on a history built to balance, and a
restarted run's log."""
import os
import tempfile
import unittest

from spoutlab import heatcorrelations as hc
from spoutlab import casefiles as sc

# air as in the C++ hand values (tests/unit/test_HeatTransfer.cpp)
AIR = dict(rho=1.0324, mu=2.029e-5, cp=1008.6, kappa=0.02917)


class Correlations(unittest.TestCase):
    def h(self, model, eps, slip):
        return hc.heat_transfer_coefficient(model, eps, slip, 8e-3, **AIR)

    def test_ranz_marshall_by_hand(self):
        # Re = 0.95 1.0324 15 8e-3/2.029e-5 = 5800.57; Pr^(1/3) = 0.888563
        # Nu = 2 + 0.6 0.888563 76.1615 = 42.6046; h = Nu 0.02917/8e-3 = 155.347
        self.assertAlmostEqual(self.h('RanzMarshall', 0.95, 15.0), 155.347, delta=2e-3)

    def test_sartori_vanishes_without_slip_and_ranz_marshall_does_not(self):
        self.assertEqual(self.h('Sartori', 0.45, 0.0), 0.0)
        self.assertAlmostEqual(self.h('RanzMarshall', 0.45, 0.0), 2 * 0.02917 / 8e-3)

    def test_gunn_is_nu_2_for_a_lone_sphere_at_rest(self):
        self.assertAlmostEqual(self.h('Gunn', 1.0, 0.0), 2 * 0.02917 / 8e-3)

    def test_unknown_model(self):
        with self.assertRaises(ValueError):
            hc.nusselt('Nusselt', 100, 0.7, 0.5)


def history(leak=0.0, steps=50, dt=0.01):
    """coupling.csv rows of a run that balances: the gas takes in `net` W,
    gives Q_k to the particles during step k + 1, and keeps the rest;
    `leak` J per step vanishes from the gas."""
    rows, Eg, Ep = [], 100.0, 50.0
    for k in range(steps + 1):
        q = 2.0 + 0.01 * k
        if k:
            Ep += rows[-1]['heat to particles [W]'] * dt
            Eg += (5.0 - q) * dt - leak
        rows.append({'time [s]': k * dt, 'heat to particles [W]': q, 'heat from gas [W]': q,
                     'gas enthalpy in [W]': 8.0, 'gas enthalpy out [W]': 3.0,
                     'gas energy [J]': Eg, 'particle energy [J]': Ep})
    return rows


class EnergyBalance(unittest.TestCase):
    def test_a_balanced_history_closes_to_round_off(self):
        pairwise, balance = hc.energy_balance(history())
        self.assertEqual(pairwise, 0.0)
        self.assertLess(balance, 1e-12)

    def test_a_leak_shows_as_its_share_of_the_particles_heat(self):
        rows = history(leak=1e-3)
        dEp = rows[-1]['particle energy [J]'] - rows[0]['particle energy [J]']
        _, balance = hc.energy_balance(rows)
        self.assertAlmostEqual(balance, 50 * 1e-3 / dEp, places=9)


def drying_history(leak=0.0, steps=40, dt=0.01):
    """coupling.csv rows of a drying run that balances, built as the solver
    keeps its books (docs/DESIGN.md §3.8): in step k the particles lose
    m_k dt of water, which the gas receives with its enthalpy c_pv T_p
    (sensible) and h_c (latent); the particles are handed Q_k - m_k L_k
    during step k + 1 and lose m_k c_w T_p of capacity energy at once; the
    sorption heat m_k (L_k - h_fg) leaves the books; `leak` kg of water per
    step vanishes from the gas."""
    cw, cpv, Tp = 4186.0, 1860.0, 320.0
    hc_ = 2501e3 + (cw - cpv) * 273.15   # vapour enthalpy c_pv T + hc_, liquid c_w T
    rows, Eg, Ep, El, Wp, G = [], 100.0, 50.0, 0.0, 1e-3, 2e-4
    for k in range(steps + 1):
        q, m, L = 2.0 + 0.01 * k, 1e-6 * (1 + 0.02 * k), 2.45e6 + 100.0 * k
        hfg = 2501e3 + (cpv - cw) * (Tp - 273.15)
        vin, vout = 3e-5, 3e-5 + 0.5e-6
        if k:
            prev = rows[-1]
            Ep += (prev['heat to particles [W]'] - prev['latent heat from particles [W]']) * dt
            Ep -= m * dt * cw * Tp
            Eg += (5.0 - q + m * cpv * Tp) * dt
            El += hc_ * (m * dt + (vin - vout) * dt - leak)
            Wp -= m * dt
            G += (m + vin - vout) * dt - leak
        rows.append({'time [s]': k * dt, 'heat to particles [W]': q, 'heat from gas [W]': q,
                     'gas enthalpy in [W]': 8.0, 'gas enthalpy out [W]': 3.0,
                     'gas energy [J]': Eg, 'particle energy [J]': Ep,
                     'particle water [kg]': Wp, 'water lost by particles [kg/s]': m if k else 0.0,
                     'vapour to gas [kg/s]': m if k else 0.0, 'vapour in [kg/s]': vin,
                     'vapour out [kg/s]': vout, 'gas vapour [kg]': G,
                     'latent heat from particles [W]': m * L if k else 0.0,
                     'sorption heat [W]': m * (L - hfg) if k else 0.0,
                     'gas latent energy [J]': El, 'latent energy in [W]': hc_ * vin,
                     'latent energy out [W]': hc_ * vout})
    return rows


class DryingBalances(unittest.TestCase):
    def test_a_balanced_drying_history_closes_both_balances(self):
        pairwise, energy = hc.energy_balance(drying_history())
        self.assertEqual(pairwise, 0.0)
        self.assertLess(energy, 1e-10)
        pairwise, water = hc.water_balance(drying_history())
        self.assertEqual(pairwise, 0.0)
        self.assertLess(water, 1e-10)

    def test_lost_water_shows_in_both(self):
        rows = drying_history(leak=1e-9)
        lost = rows[0]['particle water [kg]'] - rows[-1]['particle water [kg]']
        self.assertAlmostEqual(hc.water_balance(rows)[1], 40 * 1e-9 / lost, places=6)
        self.assertGreater(hc.energy_balance(rows)[1], 1e-4)


class CouplingLog(unittest.TestCase):
    def test_a_restart_replaces_the_rows_it_repeats(self):
        case = tempfile.mkdtemp()
        os.makedirs(os.path.join(case, 'postProcessing'))
        with open(os.path.join(case, 'postProcessing', 'coupling.csv'), 'w') as f:
            f.write('time [s],x\n0,1\n0.1,2\n0.2,3\n0.3,4\n0.2,5\n0.3,6\n0.4,7\n')
        rows = sc.read_coupling_log(case)
        self.assertEqual([(r['time [s]'], r['x']) for r in rows],
                         [(0.0, 1.0), (0.1, 2.0), (0.2, 5.0), (0.3, 6.0), (0.4, 7.0)])


if __name__ == '__main__':
    unittest.main()
