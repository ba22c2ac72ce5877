#!/usr/bin/env python3
"""
Independent high-precision reference for the 2-DOF torsional drill-string model
(rotary table + bit, Stribeck-type bit friction), Navarro-Lopez et al. form.

Only mpmath + sympy (no numpy/scipy).  Run:

    python3 reference/drill_string_reference.py           # everything (about 25 s)
    python3 reference/drill_string_reference.py --quick   # skip the second precision run
    python3 reference/drill_string_reference.py --rounded # J_b=471.9, k_t=861.2, c_t=172.3

The reference numbers of docs/model_files.md ("A drill string") for
studies/models/drill_string.ini; it shares no code with the library.

State  x = (phi, w_r, w_b),  phi = theta_r - theta_b.
  phi'     = w_r - w_b
  J_r w_r' = T_m - c_t (w_r - w_b) - k_t phi - c_r w_r
  J_b w_b' = c_t (w_r - w_b) + k_t phi - c_b w_b - T_fb
  slip (w_b != 0):  T_fb = W_ob R_b mu_b(w_b) sign(w_b),
                    mu_b(w) = mu_cb + (mu_sb - mu_cb) exp(-gamma_b |w| / v_f)
  stick (w_b == 0): T_fb = T_e := c_t w_r + k_t phi   while |T_e| <= T_sb = mu_sb W_ob R_b
  (exact Filippov sliding on w_b = 0; no Karnopp band D_v).

Integrator: own arbitrary-order Taylor-series method (exact recurrences for the
exp() term), events located on the Taylor polynomial by a bracketing solver,
everything in mpmath at mp.dps = 40 (run A) and 55 (run B).
"""
import sys, time
import mpmath as mp
from mpmath import mpf

# ----------------------------------------------------------------------------
# parameters (as in studies/models/drill_string.ini, from the public codes it cites):
#   ic3guy/quantum examples/drillstring.py  (2-DOF, all of these numbers)
#   alwaysuu/active-control-for-drill-string-systems code/drillstring.m
#     (4-DOF version; same bit parameters, J_b, c_r, c_b)
PARS_STR = dict(Jr='2122', Jb='471.9698', ct='172.3067', kt='861.5336',
                cr='425', cb='50', Rb='0.155575', mucb='0.5', musb='0.8',
                gb='0.9', vf='1')


def pars():
    return {k: mpf(v) for k, v in PARS_STR.items()}


# ----------------------------------------------------------------------------
# Part (a): steady rotation, Jacobian, fold and Hopf points
def mu(P, w):
    return P['mucb'] + (P['musb'] - P['mucb']) * mp.exp(-P['gb'] * abs(w) / P['vf'])


def F_steady(P, W, w):          # torque needed for steady rotation at speed w>0
    return (P['cr'] + P['cb']) * w + W * P['Rb'] * mu(P, w)


def d_eff(P, W, w):             # effective bit damping c_b + W R mu'(w), w>0
    return P['cb'] - W * P['Rb'] * (P['musb'] - P['mucb']) * P['gb'] / P['vf'] \
        * mp.exp(-P['gb'] * w / P['vf'])


def jac(P, W, w):
    d = d_eff(P, W, w)
    return mp.matrix([[0, 1, -1],
                      [-P['kt'] / P['Jr'], -(P['ct'] + P['cr']) / P['Jr'], P['ct'] / P['Jr']],
                      [P['kt'] / P['Jb'], P['ct'] / P['Jb'], -(P['ct'] + d) / P['Jb']]])


def eigs(P, W, w):
    ev = mp.eig(jac(P, W, w), left=False, right=False)
    return sorted(ev, key=lambda z: (mp.im(z), mp.re(z)))


def w_min(P, W):                # minimiser of F_steady (F is convex); None if F increasing
    a = W * P['Rb'] * (P['musb'] - P['mucb']) * P['gb'] / P['vf'] / (P['cr'] + P['cb'])
    return P['vf'] / P['gb'] * mp.log(a) if a > 1 else None


def steady_roots(P, W, Tm):
    """all w>0 with F_steady(w) = Tm (0, 1 or 2 roots since F is convex)"""
    g = lambda w: F_steady(P, W, w) - Tm
    roots = []
    wm = w_min(P, W)
    hi = mpf(1)
    while g(hi) < 0:
        hi *= 2
    if wm is None:
        if g(mpf(0)) < 0:
            roots.append(mp.findroot(g, (mpf(0), hi), solver='anderson'))
        return roots
    if g(wm) > 0:
        return roots
    if g(mpf(0)) > 0:
        roots.append(mp.findroot(g, (mpf(0), wm), solver='anderson'))
    while g(hi) < 0 or hi <= wm:
        hi *= 2
    roots.append(mp.findroot(g, (wm, hi), solver='anderson'))
    return roots


def hopf_closed_form(P):
    """sympy: Routh-Hurwitz a1*a2-a3 = 0 for the slip Jacobian, as polynomial in d"""
    import sympy as sp
    s, Jr, Jb, ct, kt, cr, d = sp.symbols('s J_r J_b c_t k_t c_r d', real=True)
    J = sp.Matrix([[0, 1, -1], [-kt / Jr, -(ct + cr) / Jr, ct / Jr], [kt / Jb, ct / Jb, -(ct + d) / Jb]])
    cp = sp.Poly(sp.expand((s * sp.eye(3) - J).det()), s).all_coeffs()
    a1, a2, a3 = [sp.simplify(c / cp[0]) for c in cp[1:]]
    H = sp.collect(sp.expand(sp.simplify((a1 * a2 - a3) * Jr ** 2 * Jb ** 2)), d)
    subs = {Jr: sp.Rational(PARS_STR['Jr']), Jb: sp.Rational(PARS_STR['Jb']),
            ct: sp.Rational(PARS_STR['ct']), kt: sp.Rational(PARS_STR['kt']),
            cr: sp.Rational(PARS_STR['cr'])}
    Hn = sp.Poly(sp.expand(H.subs(subs)), d)
    A, B, C = [mpf(sp.Rational(c).p) / mpf(sp.Rational(c).q) for c in Hn.all_coeffs()]
    disc = mp.sqrt(B * B - 4 * A * C)
    dstars = sorted([(-B - disc) / (2 * A), (-B + disc) / (2 * A)])
    return dict(a1=a1, a2=a2, a3=a3, H=H, dstars=dstars)


def w_of_d(P, W, d):            # invert d_eff(w) = d  (w>0 or None)
    q = (P['cb'] - d) / (W * P['Rb'] * (P['musb'] - P['mucb']) * P['gb'] / P['vf'])
    if q <= 0 or q >= 1:
        return None
    return -P['vf'] / P['gb'] * mp.log(q)


def part_a(W_list, Tm_samples):
    P = pars()
    print('=' * 78)
    print('PART (a): steady rotation, eigenvalues, fold / Hopf points   (mp.dps=%d)' % mp.mp.dps)
    hc = hopf_closed_form(P)
    print('sympy: char. poly s^3 + a1 s^2 + a2 s + a3 of slip Jacobian, d = c_b + W_ob R_b mu_b\'(w):')
    print('   a1 =', hc['a1']); print('   a2 =', hc['a2']); print('   a3 =', hc['a3'])
    print('   Hopf (Routh-Hurwitz) condition  (a1 a2 - a3) J_r^2 J_b^2 = 0 :')
    print('   ', hc['H'])
    print('   fold (real eigenvalue 0): a3 = 0  <=>  d = -c_r  <=>  dF/dw = 0')
    print('   roots d* of Hopf condition (this parameter set):', [mp.nstr(x, 25) for x in hc['dstars']])
    for W in W_list:
        W = mpf(W)
        WR = W * P['Rb']
        print('-' * 78)
        print('W_ob = %s N :  T_sb = mu_sb W_ob R_b = %s N m' % (mp.nstr(W, 10), mp.nstr(P['musb'] * WR, 20)))
        wm = w_min(P, W)
        if wm is not None:
            print('  fold (min of T_m(w)) : w = %s rad/s, T_m = %s N m' % (mp.nstr(wm, 20), mp.nstr(F_steady(P, W, wm), 20)))
        print('  steady rotation exists (w>0) for T_m > T_fold; 2 branches for T_fold < T_m < T_sb')
        for ds in hc['dstars']:
            w = w_of_d(P, W, ds)
            if w is None:
                print('  d* = %s not attained for this W_ob' % mp.nstr(ds, 12)); continue
            Tm = F_steady(P, W, w)
            ev = eigs(P, W, w)
            print('  closed form: d*=%s -> w*=%s rad/s, T_m*=%s N m' % (mp.nstr(ds, 15), mp.nstr(w, 25), mp.nstr(Tm, 25)))
            print('     eigenvalues there:', ', '.join(mp.nstr(z, 12) for z in ev))
        # numerical Hopf: root of Re(complex pair) as a function of T_m on the upper branch
        def re_pair(Tm):
            w = steady_roots(P, W, Tm)[-1]
            ev = eigs(P, W, w)
            cpx = [z for z in ev if abs(mp.im(z)) > mpf(10) ** (-mp.mp.dps // 2)]
            if not cpx:
                raise ValueError('no complex pair')
            return max(mp.re(z) for z in cpx)
        Tf = F_steady(P, W, wm) if wm is not None else mpf(0)
        # scan T_m on the upper branch for sign changes of Re(pair)
        Ttop = 2 * P['musb'] * WR
        grid = [Tf + (Ttop - Tf) * (mpf(k) / 400) ** 2 for k in range(1, 401)]
        prev = None
        for Tm in grid:
            try:
                r = re_pair(Tm)
            except ValueError:
                prev = None; continue
            if prev is not None and mp.sign(r) != mp.sign(prev[1]):
                Th = mp.findroot(re_pair, (prev[0], Tm), solver='anderson', tol=mpf(10) ** (-mp.mp.dps + 5))
                w = steady_roots(P, W, Th)[-1]
                ev = eigs(P, W, w)
                om = max(abs(mp.im(z)) for z in ev)
                print('  numeric (findroot on Re of complex pair, upper branch): T_m,Hopf = %s N m' % mp.nstr(Th, 25))
                print('     w = %s rad/s, omega = %s rad/s (2pi/omega = %s s)' % (mp.nstr(w, 20), mp.nstr(om, 20), mp.nstr(2 * mp.pi / om, 15)))
                print('     upper-branch rotation is %s for T_m > T_m,Hopf' % ('stable' if re_pair(Th * (1 + mpf('1e-6'))) < 0 else 'UNSTABLE'))
            prev = (Tm, r)
        for Tm in Tm_samples.get(float(W), []):
            Tm = mpf(Tm)
            print('  T_m = %s N m:' % mp.nstr(Tm, 10))
            rts = steady_roots(P, W, Tm)
            if not rts:
                print('     no steady rotation (w>0)')
            for w in rts:
                phi = (Tm - P['cr'] * w) / P['kt']
                ev = eigs(P, W, w)
                st = 'stable' if max(mp.re(z) for z in ev) < 0 else 'unstable'
                print('     w = %s rad/s, phi = %s rad, d = %s  [%s]' % (mp.nstr(w, 20), mp.nstr(phi, 20), mp.nstr(d_eff(P, W, w), 12), st))
                print('        eig:', ', '.join(mp.nstr(z, 15) for z in ev))
            if Tm <= P['musb'] * WR:
                print('     stuck equilibrium exists: w_r = w_b = 0, phi = T_m/k_t = %s rad (|T_e| = T_m <= T_sb)' % mp.nstr(Tm / P['kt'], 20))


# ----------------------------------------------------------------------------
# Part (b): event-driven Filippov integration with a Taylor-series method
class Model:
    def __init__(self, Tm, W, tol, order):
        P = pars()
        self.__dict__.update(P)
        self.Tm, self.W = mpf(Tm), mpf(W)
        self.WR = self.W * self.Rb
        self.Tsb = self.musb * self.WR
        self.dmu = self.musb - self.mucb
        self.tol, self.N = mpf(tol), order

    # Taylor coefficients of the solution through x0 in mode m (+1, -1 slip; 0 stick)
    def taylor(self, x0, m):
        N = self.N
        phi, wr, wb = [x0[0]], [x0[1]], [x0[2]]
        if m == 0:
            for n in range(N):
                f_phi = wr[n]
                f_wr = (self.Tm if n == 0 else 0) - (self.ct + self.cr) * wr[n] - self.kt * phi[n]
                phi.append(f_phi / (n + 1)); wr.append(f_wr / self.Jr / (n + 1)); wb.append(mpf(0))
            return [phi, wr, wb]
        g = self.gb * m / self.vf
        E = [mp.exp(-g * wb[0])]
        for n in range(N):
            rel = wr[n] - wb[n]
            phi.append(rel / (n + 1))
            wr.append(((self.Tm if n == 0 else 0) - self.ct * rel - self.kt * phi[n] - self.cr * wr[n]) / self.Jr / (n + 1))
            wb.append((self.ct * rel + self.kt * phi[n] - self.cb * wb[n]
                       - self.WR * m * ((self.mucb if n == 0 else 0) + self.dmu * E[n])) / self.Jb / (n + 1))
            s = mp.fsum((k + 1) * wb[k + 1] * E[n - k] for k in range(n + 1))
            E.append(-g * s / (n + 1))
        return [phi, wr, wb]

    def stepsize(self, c, x0):
        N = self.N
        eps = self.tol * max(1, max(abs(v) for v in x0))
        h1 = min((eps / max(abs(ci[N - 1]), mpf(10) ** -300)) ** (mpf(1) / (N - 1)) for ci in c)
        h2 = min((eps / max(abs(ci[N]), mpf(10) ** -300)) ** (mpf(1) / N) for ci in c)
        return min(h1, h2) * mpf('0.5')

    @staticmethod
    def peval(cj, t):
        return mp.polyval(cj[::-1], t)

    @staticmethod
    def pder(cj):
        return [k * cj[k] for k in range(1, len(cj))]

    def bracket(self, gfun, a, b):
        r = mp.findroot(gfun, (a, b), solver='anderson', tol=self.tol ** 2 / 100, maxsteps=400)
        return r

    def te(self, x):   # torque transmitted to the bit at w_b = 0
        return self.ct * x[1] + self.kt * x[0]

    def run_orbit(self, x_exit, track=True, tmax=400):
        """start at a stick exit (w_b=0, T_e=+T_sb), slip+ ... until the next stick exit.
        returns dict with next exit state, period, stick time, maxima."""
        x = list(x_exit); m = 1; t = mpf(0)
        t_entry = None; maxwb = mpf(0); maxwr = x[1]; minwb = mpf(0)
        first = True
        while True:
            c = self.taylor(x, m)
            h = self.stepsize(c, x)
            # event functions on the polynomial
            if m != 0:
                gf = lambda s: m * self.peval(c[2], s)
            else:
                gf = lambda s: self.ct * self.peval(c[1], s) + self.kt * self.peval(c[0], s) - self.Tsb
                gf2 = lambda s: -self.Tsb - (self.ct * self.peval(c[1], s) + self.kt * self.peval(c[0], s))
            K = 8
            taus = [h * k / K for k in range(K + 1)]
            ev_tau, ev_kind = None, None
            for k in range(1, K + 1):
                a, b = taus[k - 1], taus[k]
                if m != 0:
                    ga, gb = gf(a), gf(b)
                    if ga > 0 and gb <= 0:   # g(0) = 0 exactly right after exit/reversal; g>0 just after
                        ev_tau, ev_kind = self.bracket(gf, a, b), 'w_b=0'; break
                else:
                    if gf(a) < 0 and gf(b) >= 0:
                        ev_tau, ev_kind = self.bracket(gf, a, b), 'exit+'; break
                    if gf2(a) < 0 and gf2(b) >= 0:
                        ev_tau, ev_kind = self.bracket(gf2, a, b), 'exit-'; break
            tend = ev_tau if ev_tau is not None else h
            if track:   # local maxima of w_b and w_r inside [0, tend]
                for j in (1, 2):
                    dc = self.pder(c[j])
                    df = lambda s: self.peval(dc, s)
                    for k in range(1, K + 1):
                        a, b = tend * (k - 1) / K, tend * k / K
                        if df(a) > 0 and df(b) <= 0:
                            r = self.bracket(df, a, b)
                            v = self.peval(c[j], r)
                            if j == 2: maxwb = max(maxwb, v)
                            else: maxwr = max(maxwr, v)
                    vend = self.peval(c[j], tend)
                    if j == 2: maxwb = max(maxwb, vend); minwb = min(minwb, vend)
                    else: maxwr = max(maxwr, vend)
            x = [self.peval(cj, tend) for cj in c]
            t += tend
            first = False
            if ev_kind == 'w_b=0':
                x[2] = mpf(0)
                T = self.te(x)
                if abs(T) <= self.Tsb:
                    m = 0; t_entry = t; x_entry = list(x)
                else:          # crossing through w_b = 0 (reversal)
                    m = -m; first = True
            elif ev_kind in ('exit+', 'exit-'):
                if ev_kind == 'exit-':
                    raise RuntimeError('stick exit in negative direction: not the orbit type assumed')
                x[2] = mpf(0)
                return dict(x_exit=x, T=t, t_stick=t - t_entry, t_entry=t_entry, x_entry=x_entry,
                            maxwb=maxwb, maxwr=maxwr, minwb=minwb)
            if t > tmax:
                raise RuntimeError('no stick exit before tmax (bit stays stuck or keeps rotating), mode=%d' % m)

    def exit_state(self, wr):
        return [(self.Tsb - self.ct * wr) / self.kt, wr, mpf(0)]

    def P(self, wr, track=False):
        return self.run_orbit(self.exit_state(wr), track=track)


def part_b(Tm, W, wr_guess, dps, tol, order, settle=3, verbose=True):
    mp.mp.dps = dps
    M = Model(Tm, W, tol, order)
    t0 = time.time()
    wr = mpf(wr_guess)
    for i in range(settle):   # settle on the attractor by iterating the return map
        wr_new = M.P(wr)['x_exit'][1]
        if verbose:
            print('   settle it %d: w_r,exit = %s  (change %s)' % (i, mp.nstr(wr_new, 20), mp.nstr(wr_new - wr, 3)))
        wr = wr_new
    # Newton/secant on the 1-D return map  P(w) - w = 0  (exit set is the line c_t w_r + k_t phi = T_sb)
    G = lambda w: M.P(w)['x_exit'][1] - w
    wstar = mp.findroot(G, (wr, wr * (1 + mpf(10) ** -8)), solver='secant', tol=M.tol ** 2, maxsteps=50)
    res = M.P(wstar, track=True)
    # multiplier (derivative of the 1-D map) by central difference
    dw = mpf(10) ** (-dps // 3)
    lam = (M.P(wstar + dw)['x_exit'][1] - M.P(wstar - dw)['x_exit'][1]) / (2 * dw)
    res.update(wstar=wstar, lam=lam, resid=res['x_exit'][1] - wstar, cpu=time.time() - t0, M=M)
    return res


def show_orbit(r, label):
    M = r['M']
    print('  [%s] dps=%d tol=%s order=%d   cpu %.1f s' % (label, mp.mp.dps, mp.nstr(M.tol, 3), M.N, r['cpu']))
    xs = M.exit_state(r['wstar'])
    print('    period T              =', mp.nstr(r['T'], 30))
    print('    stick duration        =', mp.nstr(r['t_stick'], 30))
    print('    slip duration         =', mp.nstr(r['T'] - r['t_stick'], 30))
    print('    max w_b               =', mp.nstr(r['maxwb'], 30))
    print('    max w_r               =', mp.nstr(r['maxwr'], 30))
    print('    min w_b (slip)        =', mp.nstr(r['minwb'], 5))
    print('    stick exit  phi       =', mp.nstr(xs[0], 30))
    print('    stick exit  w_r       =', mp.nstr(xs[1], 30))
    print('    stick entry phi, w_r  =', mp.nstr(r['x_entry'][0], 30), mp.nstr(r['x_entry'][1], 30))
    print('    fixed-point residual  =', mp.nstr(r['resid'], 3))
    print('    return-map multiplier dP/dw_r =', mp.nstr(r['lam'], 15))


def main():
    quick = '--quick' in sys.argv
    if '--rounded' in sys.argv:
        # rounded values, for comparison: not the model file's
        PARS_STR.update(Jb='471.9', kt='861.2', ct='172.3')
    print('parameters:', PARS_STR)
    mp.mp.dps = 30
    part_a(['50000', '97347'], {50000.0: ['5500', '6000'], 97347.0: ['10000']})
    cases = [('10000', '97347', '2.3535'), ('5500', '50000', '2.0848')]
    if quick:
        cases = cases[:1]
    for Tm, W, g in cases:
        print('=' * 78)
        print('PART (b): stick-slip periodic orbit, T_m = %s N m, W_ob = %s N' % (Tm, W))
        rA = part_b(Tm, W, g, dps=40, tol='1e-34', order=40)
        show_orbit(rA, 'run A')
        if not quick:
            rB = part_b(Tm, W, rA['wstar'], dps=55, tol='1e-48', order=56, settle=0, verbose=False)
            show_orbit(rB, 'run B')
            mp.mp.dps = 40
            for k in ('T', 't_stick', 'maxwb', 'maxwr', 'wstar'):
                d = abs(rA[k] - rB[k]) / abs(rB[k])
                print('    rel. diff A vs B  %-8s %s' % (k, mp.nstr(d, 3)))


if __name__ == '__main__':
    main()
