"""Earth constants (SI).

R_E = 6378.137 km (WGS-84 equatorial radius, Vallado 4th ed. Table D-3): the
thesis text says 6375 km (p. 3-3) but its printed step sizes (17.7 s for 5
periods in 1500 steps, 26.55 s for 50 periods in 10,000) need an orbital period
of about 5310 s, i.e. r0 ≈ 6578 km at 200 km altitude (docs/sources.md, "The thesis").
"""

MU_EARTH = 3.986004418e14  # m^3/s^2, EGM-96 / WGS-84 GM (Vallado Table D-3)
R_EARTH = 6378.137e3  # m, WGS-84 equatorial radius
OMEGA_EARTH = 7.292115e-5  # rad/s, Earth's rotation rate (Vallado Eq 3-39 value)
CD_DEFAULT = 2.0  # drag coefficient of every body (thesis p. 3-9)
TETHER_AREA = 1e-6  # m^2: the thesis's assumed 1 mm^2 cross-section (p. 3-1)
J2_EARTH = 1.08262668e-3  # 1, Earth's second zonal harmonic (EGM-96, Vallado Table D-3)
