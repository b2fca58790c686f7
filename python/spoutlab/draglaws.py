"""The drag laws of couplingProperties written out again for the evaluate
scripts, from the formulas of docs/DESIGN.md §3.3 and the laws' papers, so a
verification case compares the solver with the law and not with the
solver's own code (coupling/ is not used here).

Convention (the solver's, Tsuji model A): beta [kg m^-3 s^-1] is the drag
per unit mixture volume and unit slip w = |u - v|, u interstitial:
    gas:      ... = -eps grad(p) + beta (Us - u)
    particle: F_i = V_i beta/(1 - eps) (u - v_i) - V_i grad(p)
so a fixed bed at superficial velocity u_s has -dp/dz = beta u_s/eps^2
(packed_bed_gradient), and a particle alone in a cell feels
V beta/(1 - eps) w (single_particle_drag).  Re = eps rho w d/mu for all.

Standard library only.
"""
import math

from spoutlab import foamfile


def reynolds(eps, d, w, rho, mu):
    return eps * rho * w * d / mu


class Gidaspow:
    """Ergun below eps_s, Wen-Yu above (the source papers); switch 'sharp'
    jumps at eps_s, 'smooth' blends with the Huilin-Gidaspow weight
    phi = 1/2 + atan(262.5 (eps - eps_s))/pi."""

    def __init__(self, switch='sharp', epsilon_switch=0.8):
        if switch not in ('sharp', 'smooth'):
            raise ValueError("Gidaspow switch must be sharp or smooth, got '%s'" % switch)
        self.switch = switch
        self.epsilon_switch = epsilon_switch

    @staticmethod
    def ergun(eps, d, w, rho, mu):
        return 150 * (1 - eps)**2 * mu / (eps * d * d) + 1.75 * (1 - eps) * rho * w / d

    @staticmethod
    def wen_yu(eps, d, w, rho, mu):
        re_p = reynolds(eps, d, w, rho, mu)
        # C_d w, not C_d: 24/Re w = 24 mu/(eps rho d) stays finite at w = 0
        if re_p >= 1000:
            cd_w = 0.44 * w
        else:
            cd_w = 24 * mu / (eps * rho * d) * (1 + 0.15 * re_p**0.687)
        return 0.75 * cd_w * rho * eps * (1 - eps) / d * eps**-2.65

    def beta(self, eps, d, w, rho, mu):
        if self.switch == 'sharp':
            law = self.ergun if eps < self.epsilon_switch else self.wen_yu
            return law(eps, d, w, rho, mu)
        phi = 0.5 + math.atan(262.5 * (eps - self.epsilon_switch)) / math.pi
        return (1 - phi) * self.ergun(eps, d, w, rho, mu) + phi * self.wen_yu(eps, d, w, rho, mu)

    def describe(self):
        return 'Gidaspow (%s switch at eps = %g)' % (self.switch, self.epsilon_switch)


class DiFelice:
    """Di Felice (1994): the single-sphere drag on the superficial slip with
    Dallavalle's C_d = (0.63 + 4.8/sqrt(Re))^2, times eps^-chi,
    chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2/2); per particle
    F = C_d pi d^2/8 rho (eps w)^2 eps^-chi."""

    def beta(self, eps, d, w, rho, mu):
        if w <= 0:
            return 0.0
        re_p = reynolds(eps, d, w, rho, mu)
        cd = (0.63 + 4.8 / math.sqrt(re_p))**2
        chi = 3.7 - 0.65 * math.exp(-(1.5 - math.log10(re_p))**2 / 2)
        force = cd * math.pi * d * d / 8 * rho * (eps * w)**2 * eps**-chi
        # F = V beta/(1 - eps) w
        return force * (1 - eps) / (math.pi / 6 * d**3 * w)

    def describe(self):
        return 'Di Felice'


class Beetstra:
    """Beetstra, van der Hoef and Kuipers (2007), monodisperse: the drag on
    one particle over the Stokes drag 3 pi mu d eps w,
      F = 10 phi/eps^2 + eps^2 (1 + 1.5 sqrt(phi))
        + 0.413 Re/(24 eps^2) (1/eps + 3 eps phi + 8.4 Re^-0.343)
                             / (1 + 10^(3 phi) Re^-(1 + 4 phi)/2),
    phi = 1 - eps."""

    def beta(self, eps, d, w, rho, mu):
        phi = 1 - eps
        f = 10 * phi / eps**2 + eps**2 * (1 + 1.5 * math.sqrt(phi))
        if w > 0:
            re_p = reynolds(eps, d, w, rho, mu)
            f += (0.413 * re_p / (24 * eps**2) * (1 / eps + 3 * eps * phi + 8.4 * re_p**-0.343)
                  / (1 + 10**(3 * phi) * re_p**(-(1 + 4 * phi) / 2)))
        # V beta/(1 - eps) w = 3 pi mu d eps w F
        return 3 * math.pi * mu * d * eps * f * (1 - eps) / (math.pi / 6 * d**3)

    def describe(self):
        return 'Beetstra'


def packed_bed_gradient(law, eps, d, u_s, rho, mu):
    """-dp/dz [Pa/m] through a fixed bed of voidage eps at superficial
    velocity u_s: the gas balance eps dp/dz = -beta u with u = u_s/eps."""
    u = u_s / eps
    return law.beta(eps, d, u, rho, mu) * u / eps


def single_particle_drag(law, eps, d, w, rho, mu):
    """Drag [N] on a sphere of diameter d alone in a cell of voidage eps at
    slip w: V beta/(1 - eps) w.  Every law's beta carries the factor
    (1 - eps), so eps = 1 (the isolated sphere) is taken as 1 - 1e-12."""
    eps = min(eps, 1 - 1e-12)
    return math.pi / 6 * d**3 * law.beta(eps, d, w, rho, mu) / (1 - eps) * w


def from_coupling_properties(path='constant/couplingProperties'):
    """The law a case selects: dragModel and its <name>Props, as the solver
    reads them (defaults of docs/DESIGN.md §3.3).  An unknown name stops
    with one line naming the file and the key."""
    selection = foamfile.read(path)
    name = selection.get('dragModel')
    props = selection.get(name + 'Props') if isinstance(name, str) else None
    if not isinstance(props, dict):
        props = {}
    if name == 'Gidaspow':
        switch = props.get('switch') or 'sharp'
        eps_s = float(props.get('epsilonSwitch') or 0.8)
        if switch not in ('sharp', 'smooth'):
            raise SystemExit("%s: key 'GidaspowProps/switch' expected sharp or smooth, got '%s'"
                             % (path, switch))
        return Gidaspow(switch, eps_s)
    if name == 'DiFelice':
        return DiFelice()
    if name == 'Beetstra':
        return Beetstra()
    raise SystemExit("%s: key 'dragModel' expected one of Beetstra, DiFelice, Gidaspow, got '%s'"
                     % (path, name))
