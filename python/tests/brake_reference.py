"""An independent event-driven integrator of the mode-coupling brake model
(Hoffmann et al. 2002; docs/theory.md, "Mode coupling") with its own stick
handling, for checking stickslip's orbits: SciPy's DOP853 (Hairer, Norsett &
Wanner, an explicit Runge-Kutta method of order 8) with its own root finding
on the dense output, nothing shared with the library's Taylor flow.

Coulomb friction, state (x, x', y, y'):
  slip:  x'' = -2b x' - k11 x - k12 y + (1 - g y) F,  F = +mu_k below the belt, -mu_k above
         y'' = -2b y' - k12 x - k22 y
  stick: x' = v while |2b v + k11 x + k12 y| <= mu_s (1 - g y); y as above.
"""
import math

import numpy as np
from scipy.integrate import solve_ivp

BELOW, STICK, ABOVE = -1, 0, 1


class Brake:
    def __init__(self, beta, k11, k22, k12, gamma, v, mu_s, mu_k, rtol=1e-13, atol=1e-13):
        self.b, self.k11, self.k22, self.k12 = beta, k11, k22, k12
        self.g, self.v, self.mu_s, self.mu_k = gamma, v, mu_s, mu_k
        self.rtol, self.atol = rtol, atol

    def holding(self, z):
        return 2 * self.b * self.v + self.k11 * z[0] + self.k12 * z[2]

    def limit(self, z):
        return self.mu_s * (1 - self.g * z[2])

    def field(self, mode):
        b, k11, k12, k22, g = self.b, self.k11, self.k12, self.k22, self.g
        f = -mode * self.mu_k  # below (mode -1): +mu_k

        def rhs(_, z):
            ydd = -2 * b * z[3] - k12 * z[0] - k22 * z[2]
            if mode == STICK:
                return [self.v, 0.0, z[3], ydd]
            xdd = -2 * b * z[1] - k11 * z[0] - k12 * z[2] + (1 - g * z[2]) * f
            return [z[1], xdd, z[3], ydd]
        return rhs

    def events(self, mode):
        def contact_open(_, z):
            return 1 - self.g * z[2]
        contact_open.terminal, contact_open.direction = True, -1
        if mode == STICK:
            def exit_below(_, z):
                return self.holding(z) - self.limit(z)

            def exit_above(_, z):
                return self.holding(z) + self.limit(z)
            exit_below.terminal, exit_below.direction = True, 1
            exit_above.terminal, exit_above.direction = True, -1
            return [exit_below, exit_above, contact_open]

        def arrive(_, z):
            return z[1] - self.v
        arrive.terminal, arrive.direction = True, -mode  # below: x' rises to v
        return [arrive, contact_open]

    def after_arrival(self, mode, z):
        """Filippov's rule on x' = v: stick within the static limit, else cross."""
        lam, lim = self.holding(z), self.limit(z)
        if abs(lam) <= lim:
            return STICK
        return BELOW if lam > 0 else ABOVE

    def run_to_exit(self, z0, exits=1, t_max=1e3):
        """From a stick exit into slip below at z0 to the `exits`-th stick exit:
        (t, z, status), status 'exit', 'contact-open' or 'time'."""
        t, z, mode, seen = 0.0, np.array(z0, float), BELOW, 0
        if self.holding(z) < 0:
            mode = ABOVE
        while t < t_max:
            sol = solve_ivp(self.field(mode), (t, t_max), z, method="DOP853", rtol=self.rtol,
                            atol=self.atol, events=self.events(mode))
            if sol.status != 1:
                return t, z, "time"
            k = next(i for i, e in enumerate(sol.t_events) if len(e))
            t, z = sol.t_events[k][0], np.array(sol.y_events[k][0])
            if mode == STICK:
                if k == 2:
                    return t, z, "contact-open"
                seen += 1
                mode = BELOW if k == 0 else ABOVE
                if seen == exits:
                    return t, z, "exit"
                continue
            if k == 1:
                return t, z, "contact-open"
            z[1] = self.v  # on the surface exactly
            mode = self.after_arrival(mode, z)
        return t, z, "time"


def residual(brake, z0, period, exits=1):
    """max |P(z0) - z0| and |T - period| of the stick-exit map by this integrator."""
    t, z, status = brake.run_to_exit(z0, exits, t_max=10 * period + 100)
    if status != "exit":
        return math.inf, math.inf, status
    return float(np.max(np.abs(z - np.asarray(z0)))), abs(t - period), status
