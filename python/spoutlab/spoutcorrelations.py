"""The correlations the protocols set their results beside: Kudra et al.'s
minimum spouting velocity (eq 12 of the draft-plate paper) and Ergun's
minimum fluidisation velocity (with Wen and Yu's simple form)."""
import math

# --- Kudra et al.'s correlation for u_ms (eq 12 of the draft-plate paper) ---

def kudra_ums(g, Hb, u_exp=1.12):
    """Eq 12 as the paper uses it: Kudra's experimental u_ms (W_d = 50,
    H_e = 100 mm, H_b = 0.9 m) scaled by the correlation's dependence on
    W_d (sqrt(g W_d) and (W_d d_p/(W_i H_b))^0.084), H_e^0.15 and H_b^-0.084."""
    return (u_exp * (g.Wd / 50)**0.5 * (g.He / 100)**0.15 * (g.Wd / 50)**0.084
            * (0.9 / Hb)**0.084)


def kudra_eq12(g, Hb, phi=1.0, rho_g=1.205):
    """Eq 12 evaluated directly for the simulated geometry and bed height:
    spheres (phi = 1), air at 20 C, theta in degrees (the paper does not say;
    degrees reproduce its scaled 1.18 m/s, radians would give 40 % more)."""
    rho_p, dp = g.particles['rhop'], g.particles['dp'] / 1000
    Wd, Wi, He, Lb = g.Wd / 1000, g.Wi / 1000, g.He / 1000, g.Lb / 1000
    return (math.sqrt(9.81 * Wd) * phi**0.68 * g.theta**-0.084
            * ((rho_p - rho_g) / rho_g * He / Lb)**0.15 * (Wd * dp / (Wi * Hb))**0.084)



# --- Ergun's minimum fluidisation velocity ----------------------------------

def ergun_umf(d, rho_p, rho_g, mu, eps_mf=None, phi=1.0, g=9.81):
    """u_mf [m/s] from the Ergun equation at incipient fluidisation,
    Ar = 150 (1 - e)/(phi^2 e^3) Re + 1.75/(phi e^3) Re^2, Re = rho_g u d/mu,
    Ar = d^3 rho_g (rho_p - rho_g) g/mu^2.  Without eps_mf, Wen and Yu's
    form of it (1/(phi e^3) = 14, (1 - e)/(phi^2 e^3) = 11), the 'simple
    correlation' the no-draft paper quotes (1.746 m/s)."""
    ar = d ** 3 * rho_g * (rho_p - rho_g) * g / mu ** 2
    if eps_mf is None:
        a, b = 1.75 * 14, 150 * 11
    else:
        a, b = 1.75 / (phi * eps_mf ** 3), 150 * (1 - eps_mf) / (phi ** 2 * eps_mf ** 3)
    re = (-b + math.sqrt(b * b + 4 * a * ar)) / (2 * a)
    return re * mu / (rho_g * d)
