"""Gas-to-particle heat transfer as the draft-plate paper writes it, for the
evaluate scripts: the references the solver's answers are checked against,
written out again from the published formulas (not taken from the solver).

    Re = eps rho |v_p - u| d / mu,  Pr = c_p mu / k,  h = Nu k / d
    Ranz-Marshall (eq 6a):  Nu = 2 + 0.6 Pr^(1/3) Re^(1/2)
    Sartori et al. (eq 6b): Nu = 1.54 Pr^(1/3) Re^0.57
    Gunn (1978):            Nu = (7 - 10 eps + 5 eps^2)(1 + 0.7 Re^0.2 Pr^(1/3))
                                 + (1.33 - 2.4 eps + 1.2 eps^2) Re^0.7 Pr^(1/3)
"""


def nusselt(model, re, pr, eps):
    third = pr ** (1.0 / 3.0)
    if model == 'RanzMarshall':
        return 2.0 + 0.6 * third * re ** 0.5
    if model == 'Sartori':
        return 1.54 * third * re ** 0.57
    if model == 'Gunn':
        return ((7 - 10 * eps + 5 * eps ** 2) * (1 + 0.7 * re ** 0.2 * third)
                + (1.33 - 2.4 * eps + 1.2 * eps ** 2) * re ** 0.7 * third)
    raise ValueError('unknown heat-transfer correlation %r' % model)


def heat_transfer_coefficient(model, eps, slip, d, rho, mu, cp, kappa):
    """h [W/m2/K] for a particle of diameter d at voidage eps and slip |v - u|."""
    re = eps * rho * slip * d / mu
    return nusselt(model, re, cp * mu / kappa, eps) * kappa / d


def energy_balance(rows):
    """The energy bookkeeping of a heat-transfer run from coupling.csv rows.

    Returns (largest |gas gave - particles got| over the steps relative to
    the largest exchanged heat, relative residual of the whole run).  Row k
    holds the state after step k; the heat the gas gave in step k reaches the
    particles during step k + 1 (LIGGGHTS applies it over the next DEM
    steps), so over rows 0..N
        integral (in - out) dt = dE_gas + dE_particles + Q_N dt - Q_0 dt
    and the residual is taken relative to the heat the particles received.
    With drying (docs/DESIGN.md §3.8) the vapour's latent energy joins the
    gas (its flows and holdup), the net heat a particle is handed is
    Q - m_dot L, and the sorption heat of the bound water is spent:
        integral (in - out + latent in - latent out) dt
            = dE_gas + dE_latent + dE_particles + Q'_N dt - Q'_0 dt
              + integral sorption dt,     Q' = Q - latent heat from particles
    """
    key = {'q': 'heat to particles [W]', 'g': 'heat from gas [W]',
           'in': 'gas enthalpy in [W]', 'out': 'gas enthalpy out [W]',
           'Eg': 'gas energy [J]', 'Ep': 'particle energy [J]'}
    drying = 'latent heat from particles [W]' in rows[0]

    def handed(r):
        return r[key['q']] - (r['latent heat from particles [W]'] if drying else 0.0)

    def flows(r):
        net = r[key['in']] - r[key['out']]
        if drying:
            net += (r['latent energy in [W]'] - r['latent energy out [W]']
                    - r['sorption heat [W]'])
        return net

    def stored(r):
        return r[key['Eg']] + r[key['Ep']] + (r['gas latent energy [J]'] if drying else 0.0)

    qmax = max(abs(r[key['q']]) for r in rows)
    pairwise = max(abs(r[key['q']] - r[key['g']]) for r in rows[1:]) / qmax
    net = sum(flows(rows[k]) * (rows[k]['time [s]'] - rows[k - 1]['time [s]'])
              for k in range(1, len(rows)))
    dE = stored(rows[-1]) - stored(rows[0])
    dt_first = rows[1]['time [s]'] - rows[0]['time [s]']
    dt_last = rows[-1]['time [s]'] - rows[-2]['time [s]']
    in_flight = handed(rows[-1]) * dt_last - handed(rows[0]) * dt_first
    residual = net - dE - in_flight
    dEp = rows[-1][key['Ep']] - rows[0][key['Ep']]
    scale = sum(abs(r[key['q']]) * (r['time [s]'] - p['time [s]']) for p, r in zip(rows, rows[1:]))
    return pairwise, abs(residual) / (abs(dEp) if not drying else scale)


def water_balance(rows):
    """The water bookkeeping of a drying run from coupling.csv rows: returns
    (largest |particles lost - gas received| over the steps relative to the
    largest loss, the whole-run residual relative to the water the particles
    lost).  Per step the particles' water and the gas's vapour together
    change by what the boundaries let in and out:
        W_p,N - W_p,0 + G_N - G_0 = integral (vapour in - vapour out) dt
    """
    lost = [r['water lost by particles [kg/s]'] for r in rows]
    pairwise = (max(abs(r['water lost by particles [kg/s]'] - r['vapour to gas [kg/s]'])
                    for r in rows) / max(max(abs(x) for x in lost), 1e-300))
    net = sum((r['vapour in [kg/s]'] - r['vapour out [kg/s]']) * (r['time [s]'] - p['time [s]'])
              for p, r in zip(rows, rows[1:]))
    water_lost = rows[0]['particle water [kg]'] - rows[-1]['particle water [kg]']
    gained = rows[-1]['gas vapour [kg]'] - rows[0]['gas vapour [kg]']
    residual = water_lost + net - gained
    return pairwise, abs(residual) / max(abs(water_lost), 1e-300)
