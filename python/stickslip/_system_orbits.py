"""A ready-made batch fn for sweeps over any system of the one core."""


class system_orbits:
    """A batch fn (sweep takes it as one): stickslip.orbits(system, columns,
    threads=1, **options) on every chunk, every result column as floats
    (status as its OrbitStatus code, found, stick_slip, stable, m, contact,
    sticks, period, each state component's start, _min and _max, multiplier).
    `system` is a stickslip.System (model file), which pickles to Dask's
    workers; ChainParams and the other parameter objects do not pickle, so
    for them use scheduler="serial" or build the system inside your own fn.

        drill = stickslip.System.from_file("studies/models/drill_string.ini")
        fn = stickslip.system_orbits(drill, state=[0, 0, 0])   # from rest: stick-slip
        r = stickslip.sweep(fn, {"T_m": np.linspace(9900, 10600, 64)})
    """

    batch = True

    def __init__(self, system, **options):
        if "threads" in options:
            raise ValueError("system_orbits: a sweep's worker is one thread; do not pass threads")
        self.system = system
        self.options = options

    def __call__(self, columns):
        from . import orbits
        r = orbits(self.system, columns, threads=1, **self.options)
        return {k: v.astype(float) for k, v in r.items()}

    def __repr__(self):
        return f"system_orbits({self.system!r}, **{self.options!r})"
