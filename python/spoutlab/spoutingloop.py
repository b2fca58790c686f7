"""The minimum-spouting protocol's rules: from the steps' (u_s, dP, spouts)
to the papers' quantities (u_ms by the classifier and by the pressure drop
alone, the break-through of the packed branch, the hysteresis) and the
schedule of steps, decided as the run goes."""


# --- the minimum-spouting protocol: verdicts, u_ms, the hysteresis loop -------
# Each step of the protocol is judged by the spout classifier (spouts / does
# not spout over the step's averaging window); the rules below turn the
# steps' (u_s, dP, spouts) into the paper's quantities.

def minimum_spouting(down):
    """u_ms on the decreasing branch, the paper's criterion: the lowest
    velocity that still spouts before a slight further cut collapses the
    spout, where dP begins to rise steeply.  down: (u_s, dP, spouts) in
    decreasing u_s.  Returns (u_ms, dP_ms, dP after the collapse), or None
    if the spout never collapsed."""
    # the last collapse counts: a spout that pinched off for one step and
    # recovered below it was still a spout there
    collapse = None
    for (u, dp, spouts), (_, dp_next, spouts_next) in zip(down, down[1:]):
        if spouts and not spouts_next:
            collapse = (u, dp, dp_next)
    return collapse


def steepest_rise(down):
    """u_ms by the pressure drop alone, the paper's words taken literally:
    the step of the decreasing branch after which dP rises most steeply,
    the largest increase between successive steps.  For a bed whose regime
    the classifier does not call a spout (minimum_spouting has nothing to
    read) and as a check on it where it does.  down: (u_s, dP, spouts) in
    decreasing u_s.  Returns (u_ms, dP_ms, dP one step below) or None if dP
    never rises."""
    rises = [(dp_next - dp, u, dp, dp_next)
             for (u, dp, _), (_, dp_next, _) in zip(down, down[1:])]
    rise, u, dp, dp_next = max(rises, default=(0.0, None, None, None))
    return (u, dp, dp_next) if rise > 0 else None


def spout_reforms(up):
    """On a rising branch, the first velocity at which the bed spouts:
    (u, dP) or None."""
    for u, dp, spouts in up:
        if spouts:
            return u, dp
    return None


def break_through(packed):
    """The increasing branch from the packed bed (Fig 2): dP rises while
    the voidage expansion penetrates the bed, peaks, and falls once the
    spout breaks through.  packed: (u_s, dP, spouts) in increasing u_s.
    Returns (u at the peak, peak dP, u of the break-through, its dP): the
    peak is the highest dP up to and including the first spouting step;
    the last two are None if the bed never spouted.  None for no steps."""
    if not packed:
        return None
    first = next((k for k, (_, _, s) in enumerate(packed) if s), None)
    before = packed if first is None else packed[:first + 1]
    u_peak, dp_peak, _ = max(before, key=lambda r: r[1])
    if first is None:
        return u_peak, dp_peak, None, None
    return u_peak, dp_peak, packed[first][0], packed[first][1]


def hysteresis(packed, down):
    """The size of Fig 2's loop [Pa]: the peak dP of the packed branch minus
    dP on the decreasing branch at the same u_s (linear between its steps).
    None when the decreasing branch does not span the peak's velocity."""
    peak = break_through(packed)
    pts = sorted((u, dp) for u, dp, _ in down)
    if peak is None or len(pts) < 1:
        return None
    u = peak[0]
    tol = 1e-9
    for (u0, p0), (u1, p1) in zip(pts, pts[1:]):
        if u0 - tol <= u <= u1 + tol:
            return peak[1] - (p0 + (p1 - p0) * (u - u0) / (u1 - u0))
    if len(pts) == 1 and abs(pts[0][0] - u) < tol:
        return peak[1] - pts[0][1]
    return None


class Schedule:
    """The minimum-spouting schedule, decided as the run goes, the way it is
    done at the rig.  Two ways to begin:

      rise_from  the paper's Fig 2: start on the settled (packed) bed at
                 rise_from and raise u_s by `step` ('packed' branch) until
                 `confirm` successive steps spout (the break-through and a
                 step above it, where dP has fallen and levels off) or `top`
                 is reached; a bed that never spouts ends there;
      start      spin the bed up first (the protocol's kick), then begin the
                 decreasing branch at start.

    The decreasing branch ('down') runs from one step below the top of the
    rise (or from start) until `confirm` successive steps have collapsed or
    `stop` is reached; with `full_loop` the rise goes on to `top` and the
    fall to `stop` whatever the classifier says (the paper's whole Fig 2
    loop, a schedule the classifier's verdicts cannot change, read by dP:
    steepest_rise); with `up`, u_s then rises again ('up') until `confirm`
    successive steps spout or it is back at the top.  Steps beyond that
    only repeat a confirmed state and cost minutes each."""

    def __init__(self, step, stop, rise_from=None, top=None, start=None, up=False, confirm=2,
                 full_loop=False):
        if (rise_from is None) == (start is None):
            raise ValueError('a schedule begins either on the packed bed (rise_from) or '
                             'after a spin-up (start), not both or neither')
        if rise_from is not None and not (top is not None and top >= rise_from):
            raise ValueError('the packed branch needs a top velocity >= its first, got %r'
                             % top)
        self.step, self.stop, self.up, self.confirm = step, stop, up, confirm
        self.full_loop = full_loop
        self.rise_from, self.start = rise_from, start
        self.top = top if rise_from is not None else start
        self.tol = 1e-6 * step

    def first(self):
        return (self.rise_from, 'packed') if self.rise_from is not None else (self.start, 'down')

    def next(self, done):
        """(u_s, branch) of the step after the finished ones, or None when
        the protocol is complete.  done: (u_s, branch, spouts), oldest first."""
        def streak(branch, spouts):
            n = 0
            for _, b, s in reversed(done):
                if b != branch or s != spouts:
                    break
                n += 1
            return n

        def at(u):
            return round(u, 6)

        u, branch, spouts = done[-1]
        if branch == 'packed':
            if streak('packed', True) >= self.confirm and not self.full_loop:
                return self.lower(u)
            if u + self.step <= self.top + self.tol:
                return at(u + self.step), 'packed'
            # at the top: lower it only if it spouts there at all
            return self.lower(u) if spouts or self.full_loop else None
        if branch == 'down' and (self.full_loop or streak('down', False) < self.confirm):
            nxt = self.lower(u)
            if nxt:
                return nxt
        if not self.up or (branch == 'up' and streak('up', True) >= self.confirm):
            return None
        return (at(u + self.step), 'up') if u + self.step <= self.top + self.tol else None

    def lower(self, u):
        return (round(u - self.step, 6), 'down') if u - self.step >= self.stop - self.tol \
            else None
