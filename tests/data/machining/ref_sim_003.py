# Reference regression-level simulation of seed 003 (switching RLS adaptive cutting-force observer).
# Illustrative re-implementation for test design; NOT the paper's code or experiment. Pure Python 3.
import math, random
TS = 0.4e-3                                   # Table 2 sampling period
def bw2(fc, deriv=False):                     # 2nd-order Butterworth LPF (or s*LPF), Tustin w/ prewarp
    wd = 2/TS*math.tan(math.pi*fc*TS); c = 2/TS; z = math.sqrt(0.5)
    a0 = c*c+2*z*wd*c+wd*wd; a = [1.0, (2*wd*wd-2*c*c)/a0, (c*c-2*z*wd*c+wd*wd)/a0]
    b = [wd*wd*c, 0.0, -wd*wd*c] if deriv else [wd*wd, 2*wd*wd, wd*wd]
    return [x/a0 for x in b], a
class Filt:
    def __init__(s, ba): s.b, s.a = ba; s.x = [0.0, 0.0]; s.y = [0.0, 0.0]
    def __call__(s, u):
        y = s.b[0]*u+s.b[1]*s.x[0]+s.b[2]*s.x[1]-s.a[1]*s.y[0]-s.a[2]*s.y[1]
        s.x = [u, s.x[0]]; s.y = [y, s.y[0]]; return y
def sgn(x): return (x > 0)-(x < 0)
class RLS:                                    # exponential forgetting + trace clamp (anti-windup)
    def __init__(s, n, lam, p0, pmax, th0):
        s.n, s.lam, s.pmax = n, lam, pmax; s.th = list(th0)
        s.P = [[p0 if i == j else 0.0 for j in range(n)] for i in range(n)]
    def update(s, phi, y):
        n, P = s.n, s.P
        Pp = [sum(P[i][j]*phi[j] for j in range(n)) for i in range(n)]
        den = s.lam+sum(phi[i]*Pp[i] for i in range(n)); K = [v/den for v in Pp]
        e = y-sum(phi[i]*s.th[i] for i in range(n))
        s.th = [s.th[i]+K[i]*e for i in range(n)]
        s.P = [[(P[i][j]-K[i]*Pp[j])/s.lam for j in range(n)] for i in range(n)]
        for i in range(n):
            for j in range(i+1, n): s.P[i][j] = s.P[j][i] = 0.5*(s.P[i][j]+s.P[j][i])
        tr = sum(s.P[i][i] for i in range(n))
        if tr > s.pmax: s.P = [[x*s.pmax/tr for x in r] for r in s.P]
def run(method, scenario, JL=0.0048, BL=0.002, FCL=0.20, JLn=0.0032, BLn=0.002, FCLn=0.15,
        lam=0.99, p0=1e2, pmax=1e2, L=100, ath=5.0, T=20.0, seed=1, noise=0.01,
        match_q=True, handover='shadow', commit_end=True):
    # method: 'none' (fixed nominal observer), 'conv' (single 4-parameter RLS whenever |acc|>ath, ref [9]),
    #         'prop' (switching RLS: eq.(11) for L samples after a reversal, eq.(12) if |acc|>ath, else hold)
    random.seed(seed)
    QT, Qd, Qw, Qs, Qr = (Filt(bw2(250)), Filt(bw2(250, True)), Filt(bw2(250)), Filt(bw2(250)), Filt(bw2(250)))
    MQ = [Filt(bw2(250)) for _ in range(4)]
    R = [Filt(bw2(40, True))]+[Filt(bw2(40)) for _ in range(3)]; Ry = Filt(bw2(40))
    r4 = RLS(4, lam, p0, pmax, [JLn, BLn, 0.0, FCLn]); r3 = RLS(3, lam, p0, pmax, [JLn, BLn, 0.0])
    est = [JLn, BLn, FCLn]; prev = 'hold'; since_rev = 10**9; last = 0
    q = 2*math.pi/2**20; th = thq_prev = 0.0; ph1 = ph2 = 0.0; log = []
    for k in range(int(T/TS)):
        t = k*TS
        # load-side motion: reversals at multiples of 4 s, 15 Hz modulation for acceleration richness
        w = 8*math.sin(2*math.pi*t/8)*(1+0.3*math.sin(2*math.pi*15*t))
        wd = (2*math.pi*math.cos(2*math.pi*t/8)*(1+0.3*math.sin(2*math.pi*15*t))
              + 8*math.sin(2*math.pi*t/8)*0.3*2*math.pi*15*math.cos(2*math.pi*15*t))
        g, f1 = (0.8, 80.0) if (scenario == 'vary' and t >= 11.0) else (1.0, 100.0)
        ph1 += 2*math.pi*f1*TS; ph2 += 2*math.pi*2*f1*TS
        Fc = g*(2.0+math.sin(ph1)+math.sin(ph2))                   # simulated cutting force
        That = QT(JL*wd+BL*w+FCL*sgn(w)+Fc)+random.gauss(0, noise)  # eq.(1) through Q(s) + noise
        th += w*TS; thq = round(th/q)*q; wm = (thq-thq_prev)/TS; thq_prev = thq   # 20-bit encoder
        s = sgn(wm) if abs(wm) > 0.05 else last                     # sign with deadband/hold
        Fhat = That-(est[0]*Qd(wm)+est[1]*Qw(wm)+est[2]*Qs(s))      # eq.(2), params outside filters
        FcQ = Qr(Fc)
        u = [MQ[0](wm), MQ[1](wm), MQ[2](1.0), MQ[3](s)] if match_q else [wm, wm, 1.0, s]
        phi = [f(x) for f, x in zip(R, u)]; y = Ry(That)            # eq.(11) regressor / output
        since_rev = 0 if (last and s and s != last) else since_rev+1
        if s: last = s
        if method == 'none': mode = 'hold'
        elif method == 'conv': mode = 'rls4' if abs(phi[0]) > ath else 'hold'
        else: mode = 'rls4' if since_rev < L else ('rls3' if abs(phi[0]) > ath else 'hold')
        if method == 'prop' and mode != prev:
            if mode == 'rls3':                                       # 11 -> 12: copy 3x3 block
                r3.th = r4.th[:3]; r3.P = [row[:3] for row in r4.P[:3]]
            elif mode == 'rls4':                                     # 12 -> 11
                if handover == 'sub':                                # copy theta3 AND P3 into theta4/P4 block
                    for i in range(3):
                        r4.th[i] = r3.th[i]
                        for j in range(3): r4.P[i][j] = r3.P[i][j]
                else:                                                # 'shadow': keep parallel-run F_DC,F_CL,P4;
                    r4.th[0], r4.th[1] = r3.th[0], r3.th[1]          # copy only J_L, B_L for continuity
        if mode == 'rls4':
            r4.update(phi, y)
            if not (method == 'prop' and commit_end and since_rev < L-1):
                est = [r4.th[0], r4.th[1], r4.th[3]]
        elif mode == 'rls3':
            r3.update(phi[:3], y-est[2]*phi[3]); r4.update(phi, y)  # eq.(12) + shadow eq.(11)
            est = [r3.th[0], r3.th[1], est[2]]
        prev = mode
        log.append((t, est[0], est[1], est[2], mode, Fhat, FcQ, Fc))
    return log
def rms(v): return math.sqrt(sum(x*x for x in v)/len(v))
if __name__ == '__main__':
    for label, kw in [('A literal', dict(match_q=False, handover='sub', commit_end=False)),
                      ('B recommended', dict(match_q=True, handover='shadow', commit_end=True))]:
        for scen in ('steady', 'vary'):
            row = []
            for m in ('none', 'conv', 'prop'):
                log = run(m, scen, **kw); t0 = 1.0 if scen == 'steady' else 11.0
                e = rms([r[5]-r[6] for r in log if r[0] >= t0])
                f = [r[3] for r in log if r[0] >= 4.2]; j = [r[1] for r in log if r[0] >= 4.2]
                modes = {x: sum(1 for r in log if r[4] == x) for x in ('hold', 'rls3', 'rls4')}
                row.append(f"{m}: rms={e:.4f} FCL[{min(f):.3f},{max(f):.3f}] JL[{min(j):.5f},{max(j):.5f}] BLend={log[-1][2]:.4f} {modes}")
            print(label, scen); [print('   ', x) for x in row]
