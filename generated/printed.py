"""GENERATED FILE - DO NOT EDIT.

Model 'printed': Eqs 3.48-3.50 exactly as printed in the thesis, errata included.
Produced by `make derive` (python -m derive) from derive/; regenerate instead
of editing.  sympy 1.14.0.

State vector y (index, name, unit):
   0  delta_x      m
   1  delta_y      m
   2  theta        rad
   3  delta_x_dot  m/s
   4  delta_y_dot  m/s
   5  theta_dot    rad/s

Parameter vector p (index, name, unit, meaning):
   0  m1           kg        tip-mass
   1  m2           kg        main bus
   2  m3           kg        balloon
   3  A1           m^2       frontal area of the tip-mass
   4  A2           m^2       frontal area of the main bus
   5  A3           m^2       frontal area of the balloon
   6  a            m         COM to main bus distance
   7  b            m         COM to tip-mass distance
   8  l10          m         rest (taut) length of tether 1, tip-mass to balloon
   9  l20          m         rest (taut) length of tether 2, bus to balloon
  10  E1           N         tether 1 modulus x 1 mm^2 cross-section (N/mm^2 x mm^2)
  11  E2           N         tether 2 modulus x 1 mm^2 cross-section (N/mm^2 x mm^2)
  12  c1           N s/m     tether 1 damping coefficient
  13  c2           N s/m     tether 2 damping coefficient
  14  CD           1         drag coefficient (all bodies, thesis p. 3-9)
  15  r0           m         orbit radius of the COM
  16  mu           m^3/s^2   Earth's gravitational parameter
  17  omega        rad/s     orbital rate sqrt(mu/r0^3), Eq 3.14
  18  omega_earth  rad/s     Earth's rotation rate (atmosphere co-rotates)
  19  rho1         kg/m^3    air density at the tip-mass
  20  rho2         kg/m^3    air density at the main bus
  21  rho3         kg/m^3    air density at the balloon
"""
import math

from numba import njit

from .trig import sincos, sincos_beyond, sincos_lane

MODEL = 'printed'
DESCRIPTION = 'Eqs 3.48-3.50 exactly as printed in the thesis, errata included'
GEOMETRY = "planar"  # (δx, δy, θ): the thesis plane
ORBIT = "circular"  # the COM held on a circle of radius r0 at rate ω (Eq 3.14)
STATE = ('delta_x', 'delta_y', 'theta', 'delta_x_dot', 'delta_y_dot', 'theta_dot')
STATE_UNITS = ('m', 'm', 'rad', 'm/s', 'm/s', 'rad/s')
PARAMETERS = (
    'm1', 'm2', 'm3', 'A1', 'A2', 'A3', 'a', 'b', 'l10', 'l20', 'E1', 'E2', 'c1', 'c2', 'CD', 'r0', 'mu',
    'omega', 'omega_earth', 'rho1', 'rho2', 'rho3',
)
PARAMETER_UNITS = (
    'kg', 'kg', 'kg', 'm^2', 'm^2', 'm^2', 'm', 'm', 'm', 'm', 'N', 'N', 'N s/m', 'N s/m', '1', 'm',
    'm^3/s^2', 'rad/s', 'rad/s', 'kg/m^3', 'kg/m^3', 'kg/m^3',
)
FAMILIES = ('drag1', 'drag2', 'drag3', 'spring1', 'spring2', 'damper1', 'damper2')


@njit(cache=True, inline="always")
def rhs(t, y, p, dydt):
    """State derivative dy/dt of model 'printed' (SI; layout in generated/layout.py)."""
    delta_x = y[0]
    delta_y = y[1]
    theta = y[2]
    delta_x_dot = y[3]
    delta_y_dot = y[4]
    theta_dot = y[5]
    m1 = p[0]
    m2 = p[1]
    m3 = p[2]
    A1 = p[3]
    A2 = p[4]
    A3 = p[5]
    a = p[6]
    b = p[7]
    l10 = p[8]
    l20 = p[9]
    E1 = p[10]
    E2 = p[11]
    c1 = p[12]
    c2 = p[13]
    CD = p[14]
    r0 = p[15]
    omega = p[17]
    omega_earth = p[18]
    rho1 = p[19]
    rho2 = p[20]
    rho3 = p[21]
    sin_theta, cos_theta = sincos(theta)
    # air drag on the three bodies (3.48-3.50)
    d0 = delta_y + r0
    d1 = -d0*omega + d0*omega_earth + delta_x_dot
    d2 = delta_x*omega - delta_x*omega_earth + delta_y_dot
    d3 = (1/2)*CD
    d4 = A3*d3*rho3*math.sqrt(d1**2 + d2**2)
    d5 = b*sin_theta
    d6 = b*omega*sin_theta - d5*omega_earth - d5*theta_dot
    d7 = b*cos_theta
    d8 = d7 + r0
    d9 = d7*theta_dot - d8*omega + d8*omega_earth
    d10 = d6**2 + d9**2
    d11 = 1/math.sqrt(d10)
    d12 = a*sin_theta
    d13 = -d12*omega + d12*omega_earth + d12*theta_dot
    d14 = a*cos_theta
    d15 = -d14 + r0
    d16 = -d14*theta_dot - d15*omega + d15*omega_earth
    d17 = d13**2 + d16**2
    d18 = 1/math.sqrt(d17)
    Q_delta_x = -d1*d4
    Q_delta_y = -d2*d4
    Q_theta = -A1*d10*d3*rho1*(-d11*d5*d6 + d11*d7*d9) - A2*d17*d3*rho2*(a*d13*d18*sin_theta - d14*d16*d18)
    lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
    if lambda1 > l10:  # tether 1 taut: spring1, damper1
        t1_0 = b*cos_theta
        t1_1 = c1*(delta_x_dot - delta_y*omega + omega*t1_0 - t1_0*theta_dot)
        t1_2 = b*sin_theta
        t1_3 = -delta_x + t1_2
        t1_4 = E1*(-1 + lambda1/l10)/lambda1
        t1_5 = c1*(delta_x*omega + delta_y_dot - omega*t1_2 + t1_2*theta_dot)
        t1_6 = -delta_y + t1_0
        Q_delta_x += -t1_1 + t1_3*t1_4
        Q_delta_y += t1_4*t1_6 - t1_5
        Q_theta += t1_0*t1_1 - t1_2*t1_5 + t1_4*(b*sin_theta*t1_6 - t1_0*t1_3)
    lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
    if lambda2 > l20:  # tether 2 taut: spring2, damper2
        t2_0 = delta_y*omega
        t2_1 = a*cos_theta
        t2_2 = a*sin_theta
        t2_3 = -delta_x - t2_2
        t2_4 = E2*(-1 + lambda2/l20)/lambda2
        t2_5 = delta_x*omega + delta_y_dot
        t2_6 = -delta_y - t2_1
        t2_7 = b*sin_theta
        t2_8 = b*cos_theta
        Q_delta_x += -c2*(a*cos_theta*theta_dot + delta_x_dot - omega*t2_1 - t2_0) + t2_3*t2_4
        Q_delta_y += -c2*(omega*t2_2 - t2_2*theta_dot + t2_5) + t2_4*t2_6
        Q_theta += (
                -c2*t2_1*(delta_x_dot + omega*t2_8 - t2_0 - t2_8*theta_dot) + c2*t2_2*(-omega*t2_7 +
                t2_5 + t2_7*theta_dot) + t2_4*(t2_1*t2_3 - t2_2*t2_6))
    # accelerations from M q'' + f(q, q') = Q (Lagrange, 3.26-3.30)
    dydt[0] = delta_x_dot
    dydt[1] = delta_y_dot
    dydt[2] = theta_dot
    a0 = 2*omega
    a1 = 1/m3
    a2 = 1/r0
    a3 = omega**2
    a4 = 3*a3
    a5 = a4*delta_y
    a6 = a2*a3
    a7 = 2*r0
    a8 = a**2*m2
    a9 = b**2*m1
    a10 = 1/(a7*a8 + a7*a9)
    a11 = a10*sin_theta
    a12 = 6*a11*a3*cos_theta*r0
    dydt[3] = Q_delta_x*a1 + a0*delta_y_dot + a2*a5*delta_x
    dydt[4] = Q_delta_y*a1 - a0*delta_x_dot + a5 + (3/2)*a6*delta_x**2 + (9/2)*a6*delta_y**2
    dydt[5] = 2*Q_theta*a10*r0 + 3*a**3*a10*a3*m2*sin_theta - a11*a4*b**3*m1 - a12*a8 - a12*a9


N_TRANSCENDENTAL = 2
LANES = 8  # row stride of the lane arrays: the most lanes (AVX-512)


@njit(cache=True, inline="always")
def rhs_lanes(t, y, p, dydt, s):
    """rhs on K = len(t) <= LANES lanes: row i of y, p, dydt and of the
    scratch s (N_TRANSCENDENTAL rows) is [i*LANES, i*LANES + K).

    Each lane equals rhs bit for bit (derive/lanes.py); libm's values
    come first, lane by lane, so that the second loop vectorises.
    """
    for k in range(t.shape[0]):
        theta = y[2*LANES + k]
        s[0*LANES + k], s[1*LANES + k] = sincos_beyond(theta)
    for k in range(t.shape[0]):
        delta_x = y[0*LANES + k]
        delta_y = y[1*LANES + k]
        theta = y[2*LANES + k]
        delta_x_dot = y[3*LANES + k]
        delta_y_dot = y[4*LANES + k]
        theta_dot = y[5*LANES + k]
        m1 = p[0*LANES + k]
        m2 = p[1*LANES + k]
        m3 = p[2*LANES + k]
        A1 = p[3*LANES + k]
        A2 = p[4*LANES + k]
        A3 = p[5*LANES + k]
        a = p[6*LANES + k]
        b = p[7*LANES + k]
        l10 = p[8*LANES + k]
        l20 = p[9*LANES + k]
        E1 = p[10*LANES + k]
        E2 = p[11*LANES + k]
        c1 = p[12*LANES + k]
        c2 = p[13*LANES + k]
        CD = p[14*LANES + k]
        r0 = p[15*LANES + k]
        omega = p[17*LANES + k]
        omega_earth = p[18*LANES + k]
        rho1 = p[19*LANES + k]
        rho2 = p[20*LANES + k]
        rho3 = p[21*LANES + k]
        sin_theta, cos_theta = sincos_lane(theta, s[0*LANES + k], s[1*LANES + k])
        # air drag on the three bodies (3.48-3.50)
        d0 = delta_y + r0
        d1 = -d0*omega + d0*omega_earth + delta_x_dot
        d2 = delta_x*omega - delta_x*omega_earth + delta_y_dot
        d3 = (1/2)*CD
        d4 = A3*d3*rho3*math.sqrt(d1**2 + d2**2)
        d5 = b*sin_theta
        d6 = b*omega*sin_theta - d5*omega_earth - d5*theta_dot
        d7 = b*cos_theta
        d8 = d7 + r0
        d9 = d7*theta_dot - d8*omega + d8*omega_earth
        d10 = d6**2 + d9**2
        d11 = 1/math.sqrt(d10)
        d12 = a*sin_theta
        d13 = -d12*omega + d12*omega_earth + d12*theta_dot
        d14 = a*cos_theta
        d15 = -d14 + r0
        d16 = -d14*theta_dot - d15*omega + d15*omega_earth
        d17 = d13**2 + d16**2
        d18 = 1/math.sqrt(d17)
        Q_delta_x = -d1*d4
        Q_delta_y = -d2*d4
        Q_theta = (
                -A1*d10*d3*rho1*(-d11*d5*d6 + d11*d7*d9) - A2*d17*d3*rho2*(a*d13*d18*sin_theta
                - d14*d16*d18))
        lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
        if lambda1 > l10:  # tether 1 taut: spring1, damper1
            t1_0 = b*cos_theta
            t1_1 = c1*(delta_x_dot - delta_y*omega + omega*t1_0 - t1_0*theta_dot)
            t1_2 = b*sin_theta
            t1_3 = -delta_x + t1_2
            t1_4 = E1*(-1 + lambda1/l10)/lambda1
            t1_5 = c1*(delta_x*omega + delta_y_dot - omega*t1_2 + t1_2*theta_dot)
            t1_6 = -delta_y + t1_0
            Q_delta_x += -t1_1 + t1_3*t1_4
            Q_delta_y += t1_4*t1_6 - t1_5
            Q_theta += t1_0*t1_1 - t1_2*t1_5 + t1_4*(b*sin_theta*t1_6 - t1_0*t1_3)
        lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
        if lambda2 > l20:  # tether 2 taut: spring2, damper2
            t2_0 = delta_y*omega
            t2_1 = a*cos_theta
            t2_2 = a*sin_theta
            t2_3 = -delta_x - t2_2
            t2_4 = E2*(-1 + lambda2/l20)/lambda2
            t2_5 = delta_x*omega + delta_y_dot
            t2_6 = -delta_y - t2_1
            t2_7 = b*sin_theta
            t2_8 = b*cos_theta
            Q_delta_x += -c2*(a*cos_theta*theta_dot + delta_x_dot - omega*t2_1 - t2_0) + t2_3*t2_4
            Q_delta_y += -c2*(omega*t2_2 - t2_2*theta_dot + t2_5) + t2_4*t2_6
            Q_theta += (
                    -c2*t2_1*(delta_x_dot + omega*t2_8 - t2_0 - t2_8*theta_dot) + c2*t2_2*(-omega*t2_7
                    + t2_5 + t2_7*theta_dot) + t2_4*(t2_1*t2_3 - t2_2*t2_6))
        # accelerations from M q'' + f(q, q') = Q (Lagrange, 3.26-3.30)
        dydt[0*LANES + k] = delta_x_dot
        dydt[1*LANES + k] = delta_y_dot
        dydt[2*LANES + k] = theta_dot
        a0 = 2*omega
        a1 = 1/m3
        a2 = 1/r0
        a3 = omega**2
        a4 = 3*a3
        a5 = a4*delta_y
        a6 = a2*a3
        a7 = 2*r0
        a8 = a**2*m2
        a9 = b**2*m1
        a10 = 1/(a7*a8 + a7*a9)
        a11 = a10*sin_theta
        a12 = 6*a11*a3*cos_theta*r0
        dydt[3*LANES + k] = Q_delta_x*a1 + a0*delta_y_dot + a2*a5*delta_x
        dydt[4*LANES + k] = Q_delta_y*a1 - a0*delta_x_dot + a5 + (3/2)*a6*delta_x**2 + (9/2)*a6*delta_y**2
        dydt[5*LANES + k] = 2*Q_theta*a10*r0 + 3*a**3*a10*a3*m2*sin_theta - a11*a4*b**3*m1 - a12*a8 - a12*a9


@njit(cache=True, inline="always")
def family_forces_lanes(K, y, p, out, s):
    """family_forces on K <= LANES lanes: row i of y, p and of the scratch
    s (N_TRANSCENDENTAL rows) is [i*LANES, i*LANES + K), out[f, q] is
    row f*n_q + q of out.

    Each lane equals family_forces bit for bit (derive/lanes.py); libm's values
    come first, lane by lane, so that the second loop vectorises.
    """
    for k in range(K):
        theta = y[2*LANES + k]
        s[0*LANES + k], s[1*LANES + k] = sincos_beyond(theta)
    for k in range(K):
        delta_x = y[0*LANES + k]
        delta_y = y[1*LANES + k]
        theta = y[2*LANES + k]
        delta_x_dot = y[3*LANES + k]
        delta_y_dot = y[4*LANES + k]
        theta_dot = y[5*LANES + k]
        A1 = p[3*LANES + k]
        A2 = p[4*LANES + k]
        A3 = p[5*LANES + k]
        a = p[6*LANES + k]
        b = p[7*LANES + k]
        l10 = p[8*LANES + k]
        l20 = p[9*LANES + k]
        E1 = p[10*LANES + k]
        E2 = p[11*LANES + k]
        c1 = p[12*LANES + k]
        c2 = p[13*LANES + k]
        CD = p[14*LANES + k]
        r0 = p[15*LANES + k]
        omega = p[17*LANES + k]
        omega_earth = p[18*LANES + k]
        rho1 = p[19*LANES + k]
        rho2 = p[20*LANES + k]
        rho3 = p[21*LANES + k]
        sin_theta, cos_theta = sincos_lane(theta, s[0*LANES + k], s[1*LANES + k])
        lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
        lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
        out[0*LANES + k] = 0.0
        out[1*LANES + k] = 0.0
        out[2*LANES + k] = 0.0
        out[3*LANES + k] = 0.0
        out[4*LANES + k] = 0.0
        out[5*LANES + k] = 0.0
        out[6*LANES + k] = 0.0
        out[7*LANES + k] = 0.0
        out[8*LANES + k] = 0.0
        out[9*LANES + k] = 0.0
        out[10*LANES + k] = 0.0
        out[11*LANES + k] = 0.0
        out[12*LANES + k] = 0.0
        out[13*LANES + k] = 0.0
        out[14*LANES + k] = 0.0
        out[15*LANES + k] = 0.0
        out[16*LANES + k] = 0.0
        out[17*LANES + k] = 0.0
        out[18*LANES + k] = 0.0
        out[19*LANES + k] = 0.0
        out[20*LANES + k] = 0.0
        # drag1: drag1 as printed (3.48-3.50)
        f0_0 = b*sin_theta
        f0_1 = b*omega*sin_theta - f0_0*omega_earth - f0_0*theta_dot
        f0_2 = b*cos_theta
        f0_3 = f0_2 + r0
        f0_4 = f0_2*theta_dot - f0_3*omega + f0_3*omega_earth
        f0_5 = f0_1**2 + f0_4**2
        f0_6 = 1/math.sqrt(f0_5)
        out[0*LANES + k] = 0
        out[1*LANES + k] = 0
        out[2*LANES + k] = -1/2*A1*CD*f0_5*rho1*(-f0_0*f0_1*f0_6 + f0_2*f0_4*f0_6)
        # drag2: drag2 as printed (3.48-3.50)
        f1_0 = a*sin_theta
        f1_1 = -f1_0*omega + f1_0*omega_earth + f1_0*theta_dot
        f1_2 = a*cos_theta
        f1_3 = -f1_2 + r0
        f1_4 = -f1_2*theta_dot - f1_3*omega + f1_3*omega_earth
        f1_5 = f1_1**2 + f1_4**2
        f1_6 = 1/math.sqrt(f1_5)
        out[3*LANES + k] = 0
        out[4*LANES + k] = 0
        out[5*LANES + k] = -1/2*A2*CD*f1_5*rho2*(a*f1_1*f1_6*sin_theta - f1_2*f1_4*f1_6)
        # drag3: drag3 as printed (3.48-3.50)
        f2_0 = delta_y + r0
        f2_1 = delta_x_dot - f2_0*omega + f2_0*omega_earth
        f2_2 = delta_x*omega - delta_x*omega_earth + delta_y_dot
        f2_3 = (1/2)*A3*CD*rho3*math.sqrt(f2_1**2 + f2_2**2)
        out[6*LANES + k] = -f2_1*f2_3
        out[7*LANES + k] = -f2_2*f2_3
        out[8*LANES + k] = 0
        # spring1: spring1 as printed (3.48-3.50)
        if lambda1 > l10:
            f3_0 = b*sin_theta - delta_x
            f3_1 = E1*(-1 + lambda1/l10)/lambda1
            f3_2 = b*cos_theta
            f3_3 = -delta_y + f3_2
            out[9*LANES + k] = f3_0*f3_1
            out[10*LANES + k] = f3_1*f3_3
            out[11*LANES + k] = f3_1*(b*f3_3*sin_theta - f3_0*f3_2)
        # spring2: spring2 as printed (3.48-3.50)
        if lambda2 > l20:
            f4_0 = a*sin_theta
            f4_1 = -delta_x - f4_0
            f4_2 = E2*(-1 + lambda2/l20)/lambda2
            f4_3 = a*cos_theta
            f4_4 = -delta_y - f4_3
            out[12*LANES + k] = f4_1*f4_2
            out[13*LANES + k] = f4_2*f4_4
            out[14*LANES + k] = f4_2*(-f4_0*f4_4 + f4_1*f4_3)
        # damper1: damper1 as printed (3.48-3.50)
        if lambda1 > l10:
            f5_0 = b*cos_theta
            f5_1 = c1*(delta_x_dot - delta_y*omega + f5_0*omega - f5_0*theta_dot)
            f5_2 = b*sin_theta
            f5_3 = c1*(delta_x*omega + delta_y_dot - f5_2*omega + f5_2*theta_dot)
            out[15*LANES + k] = -f5_1
            out[16*LANES + k] = -f5_3
            out[17*LANES + k] = f5_0*f5_1 - f5_2*f5_3
        # damper2: damper2 as printed (3.48-3.50)
        if lambda2 > l20:
            f6_0 = delta_y*omega
            f6_1 = a*cos_theta
            f6_2 = a*sin_theta
            f6_3 = delta_x*omega + delta_y_dot
            f6_4 = b*cos_theta
            f6_5 = b*sin_theta
            out[18*LANES + k] = -c2*(a*cos_theta*theta_dot + delta_x_dot - f6_0 - f6_1*omega)
            out[19*LANES + k] = -c2*(f6_2*omega - f6_2*theta_dot + f6_3)
            out[20*LANES + k] = (
                    a*c2*sin_theta*(f6_3 - f6_5*omega + f6_5*theta_dot) - c2*f6_1*(delta_x_dot - f6_0
                    + f6_4*omega - f6_4*theta_dot))


@njit(cache=True, inline="always")
def tether_margins_lanes(K, y, p, g, s):
    """tether_margins on K <= LANES lanes: row i of y, p and of the scratch
    s (N_TRANSCENDENTAL rows) is [i*LANES, i*LANES + K), g[j] is row j
    of g.

    Each lane is tether_margins's value to a few ulps (sqrt for its hypot,
    derive/lanes.py); libm's values come first, lane by lane.
    """
    for k in range(K):
        theta = y[2*LANES + k]
        s[0*LANES + k], s[1*LANES + k] = sincos_beyond(theta)
    for k in range(K):
        delta_x = y[0*LANES + k]
        delta_y = y[1*LANES + k]
        theta = y[2*LANES + k]
        a = p[6*LANES + k]
        b = p[7*LANES + k]
        l10 = p[8*LANES + k]
        l20 = p[9*LANES + k]
        sin_theta, cos_theta = sincos_lane(theta, s[0*LANES + k], s[1*LANES + k])
        g[0*LANES + k] = math.sqrt((b*sin_theta - delta_x)**2 + (b*cos_theta - delta_y)**2) - l10
        g[1*LANES + k] = math.sqrt((-a*sin_theta - delta_x)**2 + (-a*cos_theta - delta_y)**2) - l20


@njit(cache=True)
def family_forces(y, p, out):
    """out[f, k] = generalized force of family FAMILIES[f] on q_k (N, N, N m)."""
    delta_x = y[0]
    delta_y = y[1]
    theta = y[2]
    delta_x_dot = y[3]
    delta_y_dot = y[4]
    theta_dot = y[5]
    A1 = p[3]
    A2 = p[4]
    A3 = p[5]
    a = p[6]
    b = p[7]
    l10 = p[8]
    l20 = p[9]
    E1 = p[10]
    E2 = p[11]
    c1 = p[12]
    c2 = p[13]
    CD = p[14]
    r0 = p[15]
    omega = p[17]
    omega_earth = p[18]
    rho1 = p[19]
    rho2 = p[20]
    rho3 = p[21]
    sin_theta, cos_theta = sincos(theta)
    lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
    lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
    out[:, :] = 0.0
    # drag1: drag1 as printed (3.48-3.50)
    f0_0 = b*sin_theta
    f0_1 = b*omega*sin_theta - f0_0*omega_earth - f0_0*theta_dot
    f0_2 = b*cos_theta
    f0_3 = f0_2 + r0
    f0_4 = f0_2*theta_dot - f0_3*omega + f0_3*omega_earth
    f0_5 = f0_1**2 + f0_4**2
    f0_6 = 1/math.sqrt(f0_5)
    out[0, 0] = 0
    out[0, 1] = 0
    out[0, 2] = -1/2*A1*CD*f0_5*rho1*(-f0_0*f0_1*f0_6 + f0_2*f0_4*f0_6)
    # drag2: drag2 as printed (3.48-3.50)
    f1_0 = a*sin_theta
    f1_1 = -f1_0*omega + f1_0*omega_earth + f1_0*theta_dot
    f1_2 = a*cos_theta
    f1_3 = -f1_2 + r0
    f1_4 = -f1_2*theta_dot - f1_3*omega + f1_3*omega_earth
    f1_5 = f1_1**2 + f1_4**2
    f1_6 = 1/math.sqrt(f1_5)
    out[1, 0] = 0
    out[1, 1] = 0
    out[1, 2] = -1/2*A2*CD*f1_5*rho2*(a*f1_1*f1_6*sin_theta - f1_2*f1_4*f1_6)
    # drag3: drag3 as printed (3.48-3.50)
    f2_0 = delta_y + r0
    f2_1 = delta_x_dot - f2_0*omega + f2_0*omega_earth
    f2_2 = delta_x*omega - delta_x*omega_earth + delta_y_dot
    f2_3 = (1/2)*A3*CD*rho3*math.sqrt(f2_1**2 + f2_2**2)
    out[2, 0] = -f2_1*f2_3
    out[2, 1] = -f2_2*f2_3
    out[2, 2] = 0
    # spring1: spring1 as printed (3.48-3.50)
    if lambda1 > l10:
        f3_0 = b*sin_theta - delta_x
        f3_1 = E1*(-1 + lambda1/l10)/lambda1
        f3_2 = b*cos_theta
        f3_3 = -delta_y + f3_2
        out[3, 0] = f3_0*f3_1
        out[3, 1] = f3_1*f3_3
        out[3, 2] = f3_1*(b*f3_3*sin_theta - f3_0*f3_2)
    # spring2: spring2 as printed (3.48-3.50)
    if lambda2 > l20:
        f4_0 = a*sin_theta
        f4_1 = -delta_x - f4_0
        f4_2 = E2*(-1 + lambda2/l20)/lambda2
        f4_3 = a*cos_theta
        f4_4 = -delta_y - f4_3
        out[4, 0] = f4_1*f4_2
        out[4, 1] = f4_2*f4_4
        out[4, 2] = f4_2*(-f4_0*f4_4 + f4_1*f4_3)
    # damper1: damper1 as printed (3.48-3.50)
    if lambda1 > l10:
        f5_0 = b*cos_theta
        f5_1 = c1*(delta_x_dot - delta_y*omega + f5_0*omega - f5_0*theta_dot)
        f5_2 = b*sin_theta
        f5_3 = c1*(delta_x*omega + delta_y_dot - f5_2*omega + f5_2*theta_dot)
        out[5, 0] = -f5_1
        out[5, 1] = -f5_3
        out[5, 2] = f5_0*f5_1 - f5_2*f5_3
    # damper2: damper2 as printed (3.48-3.50)
    if lambda2 > l20:
        f6_0 = delta_y*omega
        f6_1 = a*cos_theta
        f6_2 = a*sin_theta
        f6_3 = delta_x*omega + delta_y_dot
        f6_4 = b*cos_theta
        f6_5 = b*sin_theta
        out[6, 0] = -c2*(a*cos_theta*theta_dot + delta_x_dot - f6_0 - f6_1*omega)
        out[6, 1] = -c2*(f6_2*omega - f6_2*theta_dot + f6_3)
        out[6, 2] = (
                a*c2*sin_theta*(f6_3 - f6_5*omega + f6_5*theta_dot) - c2*f6_1*(delta_x_dot - f6_0 +
                f6_4*omega - f6_4*theta_dot))


@njit(cache=True)
def jacobi(y, p):
    """Jacobi integral h = Σ q̇ ∂L/∂q̇ − L plus taut-tether spring energy [J].

    Constant with drag and dampers off; otherwise dh/dt = power of drag and dampers.
    """
    delta_x = y[0]
    delta_y = y[1]
    theta = y[2]
    delta_x_dot = y[3]
    delta_y_dot = y[4]
    theta_dot = y[5]
    m1 = p[0]
    m2 = p[1]
    m3 = p[2]
    a = p[6]
    b = p[7]
    l10 = p[8]
    l20 = p[9]
    E1 = p[10]
    E2 = p[11]
    r0 = p[15]
    omega = p[17]
    sin_theta, cos_theta = sincos(theta)
    e0 = delta_y**2
    e1 = omega**2
    e2 = (3/2)*e1
    e3 = e2*m3
    e4 = cos_theta**2
    e5 = a**2
    e6 = theta_dot**2
    e7 = sin_theta**2
    e8 = b**2
    e9 = e4*m1
    e10 = e1/r0**2
    e11 = e10*m3
    e12 = (3/8)*e11
    e13 = 1/r0
    e14 = e13*e3
    e15 = delta_x**2
    e16 = a**3
    e17 = cos_theta**3
    e18 = (3/8)*e10
    e19 = cos_theta**4*e18
    e20 = a**4*m2
    e21 = e18*sin_theta**4
    e22 = e13*e2
    e23 = b**3*m1
    e24 = b**4
    e25 = e24*m1
    e26 = (3/4)*e10*e7
    h = (
            (3/2)*cos_theta*e1*e13*e16*e7*m2 - cos_theta*e22*e23*e7 - delta_x**4*e12 + (1/2)*
            delta_x_dot**2*m3 - delta_y**4*e12 - delta_y**3*e14 - delta_y*e14*e15 + (1/2)*
            delta_y_dot**2*m3 - 3/4*e0*e11*e15 - e0*e3 + (3/2)*e1*e13*e16*e17*m2 - e17*e22*e23 -
            e19*e20 - e19*e25 - e2*e4*e5*m2 - e2*e8*e9 - e20*e21 - e20*e26*e4 - e21*e25 - e24*
            e26*e9 + (1/2)*e4*e5*e6*m2 + (1/2)*e4*e6*e8*m1 + (1/2)*e5*e6*e7*m2 + (1/2)*e6*e7*
            e8*m1)
    lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
    if lambda1 > l10:
        h += (1/2)*E1*(-l10 + lambda1)**2/l10
    lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
    if lambda2 > l20:
        h += (1/2)*E2*(-l20 + lambda2)**2/l20
    return h


@njit(cache=True)
def jacobian(t, y, p, J):
    """J[i, j] = ∂(dy_i/dt)/∂y_j of model 'printed' (units of y_i/s per y_j)."""
    delta_x = y[0]
    delta_y = y[1]
    theta = y[2]
    delta_x_dot = y[3]
    delta_y_dot = y[4]
    theta_dot = y[5]
    m1 = p[0]
    m2 = p[1]
    m3 = p[2]
    A1 = p[3]
    A2 = p[4]
    A3 = p[5]
    a = p[6]
    b = p[7]
    l10 = p[8]
    l20 = p[9]
    E1 = p[10]
    E2 = p[11]
    c1 = p[12]
    c2 = p[13]
    CD = p[14]
    r0 = p[15]
    omega = p[17]
    omega_earth = p[18]
    rho1 = p[19]
    rho2 = p[20]
    rho3 = p[21]
    sin_theta, cos_theta = sincos(theta)
    jd0 = delta_y + r0
    jd1 = delta_x_dot - jd0*omega + jd0*omega_earth
    jd2 = delta_x*omega - delta_x*omega_earth + delta_y_dot
    jd3 = jd1*jd2
    jd4 = 2*omega
    jd5 = 2*omega_earth
    jd6 = jd4 - jd5
    jd7 = jd2**2
    jd8 = jd1**2
    jd9 = math.sqrt(jd7 + jd8)
    jd10 = 1/jd9
    jd11 = A3*rho3
    jd12 = (1/4)*CD*jd10*jd11
    jd13 = jd12*jd6
    jd14 = omega - omega_earth
    jd15 = (1/2)*CD
    jd16 = jd11*jd15
    jd17 = jd16*jd9
    jd18 = -jd12*jd6
    jd19 = jd10*jd16
    jd20 = -jd19*jd3
    jd21 = b*sin_theta
    jd22 = jd21*theta_dot
    jd23 = b*omega*sin_theta - jd21*omega_earth - jd22
    jd24 = b*cos_theta
    jd25 = jd24*theta_dot
    jd26 = jd23*(2*b*cos_theta*omega - jd24*jd5 - 2*jd25)
    jd27 = jd24 + r0
    jd28 = jd25 - jd27*omega + jd27*omega_earth
    jd29 = jd28*(2*b*omega*sin_theta - jd21*jd5 - 2*jd22)
    jd30 = jd23**2 + jd28**2
    jd31 = 1/math.sqrt(jd30)
    jd32 = jd21*jd23
    jd33 = jd24*jd28
    jd34 = A1*jd15*rho1
    jd35 = jd34*(-jd31*jd32 + jd31*jd33)
    jd36 = a*sin_theta
    jd37 = jd36*theta_dot
    jd38 = -jd36*omega + jd36*omega_earth + jd37
    jd39 = a*cos_theta
    jd40 = jd39*theta_dot
    jd41 = jd38*(-jd39*jd4 + jd39*jd5 + 2*jd40)
    jd42 = -jd39 + r0
    jd43 = -jd40 - jd42*omega + jd42*omega_earth
    jd44 = jd43*(-jd36*jd4 + jd36*jd5 + 2*jd37)
    jd45 = jd38**2 + jd43**2
    jd46 = 1/math.sqrt(jd45)
    jd47 = jd39*jd43
    jd48 = A2*jd15*rho2
    jd49 = jd48*(a*jd38*jd46*sin_theta - jd46*jd47)
    jd50 = jd21*jd31
    jd51 = jd30**(-3/2)
    jd52 = -1/2*jd26 - 1/2*jd29
    jd53 = jd30*jd34
    jd54 = jd36*jd46
    jd55 = jd36*jd38
    jd56 = jd45**(-3/2)
    jd57 = jd56*(-1/2*jd41 - 1/2*jd44)
    jd58 = jd45*jd48
    jd59 = cos_theta**2
    jd60 = b**2*jd31
    jd61 = sin_theta**2
    jd62 = jd51*(b*jd23*sin_theta - jd33)
    jd63 = a**2*jd46
    jd64 = jd56*(jd47 - jd55)
    dQ0_0 = -jd13*jd3
    dQ0_1 = jd14*jd17 - jd18*jd8
    dQ0_2 = 0
    dQ0_3 = -jd17 - jd19*jd8
    dQ0_4 = jd20
    dQ0_5 = 0
    dQ1_0 = -jd13*jd7 - jd14*jd17
    dQ1_1 = -jd18*jd3
    dQ1_2 = 0
    dQ1_3 = jd20
    dQ1_4 = -jd17 - jd19*jd7
    dQ1_5 = 0
    dQ2_0 = 0
    dQ2_1 = 0
    dQ2_2 = (
            -jd35*(jd26 + jd29) - jd49*(jd41 + jd44) - jd53*(b*cos_theta*jd28*jd51*jd52 - jd28*jd50 -
            jd32*jd51*jd52 - jd50*(b*cos_theta*omega - jd24*omega_earth - jd25)) - jd58*(jd43*jd54 -
            jd47*jd57 + jd54*(-jd39*omega + jd39*omega_earth + jd40) + jd55*jd57))
    dQ2_3 = 0
    dQ2_4 = 0
    dQ2_5 = (
            -jd35*(-2*jd32 + 2*jd33) - jd49*(2*a*jd38*sin_theta - 2*jd47) - jd53*(-jd32*jd62 +
            jd33*jd62 + jd59*jd60 + jd60*jd61) - jd58*(-jd47*jd64 + jd55*jd64 + jd59*jd63 + jd61*
            jd63))
    lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
    if lambda1 > l10:
        jt1_0 = b*cos_theta
        jt1_1 = -delta_y + jt1_0
        jt1_2 = jt1_1**2
        jt1_3 = b*sin_theta
        jt1_4 = -delta_x + jt1_3
        jt1_5 = jt1_4**2
        jt1_6 = jt1_2 + jt1_5
        jt1_7 = 1/l10
        jt1_8 = jt1_7*lambda1 - 1
        jt1_9 = E1*jt1_8
        jt1_10 = jt1_9/math.sqrt(jt1_6)
        jt1_11 = -jt1_10
        jt1_12 = jt1_6**(-3/2)
        jt1_13 = jt1_12*jt1_9
        jt1_14 = -jt1_4
        jt1_15 = 1/jt1_6
        jt1_16 = E1*jt1_15*jt1_7
        jt1_17 = jt1_16*jt1_4
        jt1_18 = c1*omega
        jt1_19 = -jt1_1
        jt1_20 = jt1_13*jt1_4
        jt1_21 = jt1_1*jt1_20
        jt1_22 = jt1_3*omega
        jt1_23 = c1*(b*sin_theta*theta_dot - jt1_22)
        jt1_24 = jt1_0*jt1_4 - jt1_1*jt1_3
        jt1_25 = -jt1_24
        jt1_26 = jt1_0*jt1_10 + jt1_20*jt1_25
        jt1_27 = -c1
        jt1_28 = c1*jt1_0
        jt1_29 = jt1_1*jt1_16
        jt1_30 = jt1_0*omega - jt1_0*theta_dot
        jt1_31 = -c1*jt1_30
        jt1_32 = -E1*jt1_1*jt1_12*jt1_25*jt1_8 + jt1_10*jt1_3
        jt1_33 = c1*jt1_3
        jt1_34 = -jt1_33
        jt1_35 = jt1_16*jt1_25
        jt1_36 = b**2
        jt1_37 = cos_theta**2*jt1_36
        jt1_38 = jt1_36*sin_theta**2
        dQ0_0 += jt1_11 + jt1_13*jt1_5 + jt1_14*jt1_17
        dQ0_1 += jt1_17*jt1_19 + jt1_18 + jt1_21
        dQ0_2 += jt1_17*jt1_24 - jt1_23 + jt1_26
        dQ0_3 += jt1_27
        dQ0_4 += 0
        dQ0_5 += jt1_28
        dQ1_0 += jt1_14*jt1_29 - jt1_18 + jt1_21
        dQ1_1 += jt1_11 + jt1_13*jt1_2 + jt1_19*jt1_29
        dQ1_2 += E1*jt1_1*jt1_15*jt1_24*jt1_7 - jt1_31 - jt1_32
        dQ1_3 += 0
        dQ1_4 += jt1_27
        dQ1_5 += jt1_34
        dQ2_0 += jt1_14*jt1_35 - jt1_18*jt1_3 + jt1_26
        dQ2_1 += E1*jt1_15*jt1_19*jt1_25*jt1_7 - jt1_0*jt1_18 - jt1_32
        dQ2_2 += (
                jt1_0*jt1_23 + jt1_10*(b*cos_theta*jt1_1 + b*jt1_4*sin_theta - jt1_37 - jt1_38) +
                jt1_13*jt1_25**2 + jt1_24*jt1_35 - jt1_28*(delta_x*omega + delta_y_dot - jt1_22 + jt1_3*
                theta_dot) - jt1_3*jt1_31 - jt1_33*(delta_x_dot - delta_y*omega + jt1_30))
        dQ2_3 += jt1_28
        dQ2_4 += jt1_34
        dQ2_5 += -c1*jt1_37 - c1*jt1_38
    lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
    if lambda2 > l20:
        jt2_0 = a*cos_theta
        jt2_1 = delta_y + jt2_0
        jt2_2 = -jt2_1
        jt2_3 = jt2_2**2
        jt2_4 = a*sin_theta
        jt2_5 = delta_x + jt2_4
        jt2_6 = -jt2_5
        jt2_7 = jt2_6**2
        jt2_8 = jt2_3 + jt2_7
        jt2_9 = 1/l20
        jt2_10 = jt2_9*lambda2 - 1
        jt2_11 = E2*jt2_10
        jt2_12 = jt2_11/math.sqrt(jt2_8)
        jt2_13 = -jt2_12
        jt2_14 = 1/jt2_8
        jt2_15 = E2*jt2_14*jt2_9
        jt2_16 = jt2_15*jt2_6
        jt2_17 = jt2_8**(-3/2)
        jt2_18 = jt2_11*jt2_17
        jt2_19 = c2*omega
        jt2_20 = jt2_18*jt2_6
        jt2_21 = jt2_2*jt2_20
        jt2_22 = jt2_0*jt2_12
        jt2_23 = -a*jt2_2*sin_theta + jt2_0*jt2_6
        jt2_24 = -jt2_23
        jt2_25 = -c2
        jt2_26 = c2*jt2_0
        jt2_27 = -jt2_26
        jt2_28 = jt2_15*jt2_2
        jt2_29 = jt2_12*jt2_4 + jt2_18*jt2_2*jt2_23
        jt2_30 = c2*jt2_4
        jt2_31 = jt2_15*jt2_23
        jt2_32 = b*cos_theta
        jt2_33 = jt2_32*omega - jt2_32*theta_dot
        jt2_34 = b*sin_theta
        jt2_35 = jt2_34*omega
        jt2_36 = a**2
        jt2_37 = cos_theta**2
        jt2_38 = sin_theta**2
        jt2_39 = a*b*c2
        dQ0_0 += jt2_13 + jt2_16*jt2_5 + jt2_18*jt2_7
        dQ0_1 += jt2_1*jt2_16 + jt2_19 + jt2_21
        dQ0_2 += (
                E2*jt2_10*jt2_17*jt2_23*jt2_6 + E2*jt2_14*jt2_24*jt2_6*jt2_9 - c2*(jt2_4*omega -
                jt2_4*theta_dot) - jt2_22)
        dQ0_3 += jt2_25
        dQ0_4 += 0
        dQ0_5 += jt2_27
        dQ1_0 += -jt2_19 + jt2_21 + jt2_28*jt2_5
        dQ1_1 += jt2_1*jt2_28 + jt2_13 + jt2_18*jt2_3
        dQ1_2 += -c2*(jt2_0*omega - jt2_0*theta_dot) + jt2_24*jt2_28 + jt2_29
        dQ1_3 += 0
        dQ1_4 += jt2_25
        dQ1_5 += jt2_30
        dQ2_0 += jt2_19*jt2_4 + jt2_20*jt2_23 - jt2_22 + jt2_31*jt2_5
        dQ2_1 += jt2_0*jt2_19 + jt2_1*jt2_31 + jt2_29
        dQ2_2 += (
                jt2_12*(-jt2_0*jt2_2 - jt2_36*jt2_37 - jt2_36*jt2_38 - jt2_4*jt2_6) + jt2_18*jt2_23**2
                + jt2_24*jt2_31 - jt2_26*(b*sin_theta*theta_dot - jt2_35) + jt2_26*(delta_x*omega +
                delta_y_dot + jt2_34*theta_dot - jt2_35) - jt2_30*jt2_33 + jt2_30*(delta_x_dot - delta_y*
                omega + jt2_33))
        dQ2_3 += jt2_27
        dQ2_4 += jt2_30
        dQ2_5 += jt2_37*jt2_39 + jt2_38*jt2_39
    J[:, :] = 0.0
    J[0, 3] = 1.0
    J[1, 4] = 1.0
    J[2, 5] = 1.0
    ja0 = 1/m3
    ja1 = 1/r0
    ja2 = omega**2
    ja3 = 3*ja2
    ja4 = ja1*ja3
    ja5 = delta_x*ja4
    ja6 = 2*omega
    ja7 = 2*r0
    ja8 = a**2*m2
    ja9 = b**2*m1
    ja10 = 1/(ja7*ja8 + ja7*ja9)
    ja11 = ja10*ja7
    ja12 = 6*ja10*ja2*r0*(cos_theta**2 - sin_theta**2)
    J[3, 0] = dQ0_0*ja0 + delta_y*ja4
    J[3, 1] = dQ0_1*ja0 + ja5
    J[3, 2] = dQ0_2*ja0
    J[3, 3] = dQ0_3*ja0
    J[3, 4] = dQ0_4*ja0 + ja6
    J[3, 5] = dQ0_5*ja0
    J[4, 0] = dQ1_0*ja0 + ja5
    J[4, 1] = dQ1_1*ja0 + 9*delta_y*ja1*ja2 + ja3
    J[4, 2] = dQ1_2*ja0
    J[4, 3] = dQ1_3*ja0 - ja6
    J[4, 4] = dQ1_4*ja0
    J[4, 5] = dQ1_5*ja0
    J[5, 0] = dQ2_0*ja11
    J[5, 1] = dQ2_1*ja11
    J[5, 2] = (
            3*a**3*cos_theta*ja10*ja2*m2 - b**3*cos_theta*ja10*ja3*m1 + 2*dQ2_2*ja10*r0 - ja12*
            ja8 - ja12*ja9)
    J[5, 3] = dQ2_3*ja11
    J[5, 4] = dQ2_4*ja11
    J[5, 5] = dQ2_5*ja11


@njit(cache=True, inline="always")
def tether_margins(y, p, g):
    """g[j] = λ_j − l_j0 [m]: tether j is taut when g[j] > 0 (Eqs 3.39-3.42)."""
    delta_x = y[0]
    delta_y = y[1]
    theta = y[2]
    a = p[6]
    b = p[7]
    l10 = p[8]
    l20 = p[9]
    sin_theta, cos_theta = sincos(theta)
    g[0] = math.hypot(b*sin_theta - delta_x, b*cos_theta - delta_y) - l10
    g[1] = math.hypot(-a*sin_theta - delta_x, -a*cos_theta - delta_y) - l20


@njit(cache=True, inline="always")
def body_radii(y, p):
    """(|R_1|, |R_2|, |R_3|) [m]: tip-mass, bus, balloon from Earth's centre.

    Positions (Eqs 3.10-3.12).
    """
    delta_x = y[0]
    delta_y = y[1]
    theta = y[2]
    a = p[6]
    b = p[7]
    r0 = p[15]
    sin_theta, cos_theta = sincos(theta)
    return (
            math.hypot(b*sin_theta, b*cos_theta + r0), math.hypot(-a*sin_theta, -a*cos_theta + r0),
            math.hypot(delta_x, delta_y + r0))
