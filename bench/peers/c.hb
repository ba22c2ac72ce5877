# AUTO-07p default settings (NTST 20, EPSL/EPSU 1e-7, EPSS 1e-5 are its defaults).
# Steady sliding x = mu(v), y = 0 from v = 0.5 down to 0.39: the Hopf point (IPS = 1).
NDIM = 2, IPS = 1, IRS = 0, ILP = 1
ICP = [1, 7]
U = {1: 0.25, 2: 0.0}
PAR = {1: 0.5}
DS = -0.01
UZSTOP = {1: 0.39}
