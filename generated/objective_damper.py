"""GENERATED FILE - DO NOT EDIT.

Model 'objective-damper': derived model with Kelvin-Voigt tether dampers (damping of the stretch rate only).
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

MODEL = 'objective-damper'
DESCRIPTION = 'derived model with Kelvin-Voigt tether dampers (damping of the stretch rate only)'
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
    """State derivative dy/dt of model 'objective-damper' (SI; layout in generated/layout.py)."""
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
    # air drag on the three bodies (3.32-3.34)
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
    d10 = math.sqrt(d6**2 + d9**2)
    d11 = a*sin_theta
    d12 = -d11*omega + d11*omega_earth + d11*theta_dot
    d13 = a*cos_theta
    d14 = -d13 + r0
    d15 = -d13*theta_dot - d14*omega + d14*omega_earth
    d16 = math.sqrt(d12**2 + d15**2)
    Q_delta_x = -d1*d4
    Q_delta_y = -d2*d4
    Q_theta = (
            (1/2)*A1*CD*b*d10*d6*rho1*sin_theta - A1*d10*d3*d7*d9*rho1 + (1/2)*A2*CD*a*
            cos_theta*d15*d16*rho2 - A2*d11*d12*d16*d3*rho2)
    lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
    if lambda1 > l10:  # tether 1 taut: spring1, damper1
        t1_0 = b*sin_theta
        t1_1 = -delta_x + t1_0
        t1_2 = 1/lambda1
        t1_3 = -1 + lambda1/l10
        t1_4 = E1*t1_3
        t1_5 = t1_2*t1_4
        t1_6 = t1_1*t1_5
        t1_7 = b*cos_theta
        t1_8 = (
                max(-t1_4, c1*(b*delta_y*sin_theta*t1_2*theta_dot + delta_x*delta_x_dot*t1_2 -
                delta_x*t1_2*t1_7*theta_dot - delta_x_dot*t1_0*t1_2 + delta_y*delta_y_dot*t1_2 -
                delta_y_dot*t1_2*t1_7)))
        t1_9 = t1_2*t1_8
        t1_10 = t1_1*t1_9
        t1_11 = -delta_y + t1_7
        Q_delta_x += t1_10 + t1_6
        Q_delta_y += t1_11*t1_5 + t1_11*t1_9
        Q_theta += E1*b*sin_theta*t1_11*t1_2*t1_3 + b*sin_theta*t1_11*t1_2*t1_8 - t1_10*t1_7 - t1_6*t1_7
    lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
    if lambda2 > l20:  # tether 2 taut: spring2, damper2
        t2_0 = a*sin_theta
        t2_1 = -delta_x - t2_0
        t2_2 = 1/lambda2
        t2_3 = E2*(-1 + lambda2/l20)
        t2_4 = t2_2*t2_3
        t2_5 = t2_1*t2_4
        t2_6 = delta_x_dot*t2_2
        t2_7 = delta_y_dot*t2_2
        t2_8 = a*cos_theta
        t2_9 = t2_2*theta_dot
        t2_10 = (
                t2_2*max(-t2_3, c2*(delta_x*t2_6 + delta_x*t2_8*t2_9 - delta_y*t2_0*t2_9 + delta_y*
                t2_7 + t2_0*t2_6 + t2_7*t2_8)))
        t2_11 = t2_1*t2_10
        t2_12 = -delta_y - t2_8
        t2_13 = t2_12*t2_4
        t2_14 = t2_10*t2_12
        Q_delta_x += t2_11 + t2_5
        Q_delta_y += t2_13 + t2_14
        Q_theta += -t2_0*t2_13 - t2_0*t2_14 + t2_11*t2_8 + t2_5*t2_8
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
        # air drag on the three bodies (3.32-3.34)
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
        d10 = math.sqrt(d6**2 + d9**2)
        d11 = a*sin_theta
        d12 = -d11*omega + d11*omega_earth + d11*theta_dot
        d13 = a*cos_theta
        d14 = -d13 + r0
        d15 = -d13*theta_dot - d14*omega + d14*omega_earth
        d16 = math.sqrt(d12**2 + d15**2)
        Q_delta_x = -d1*d4
        Q_delta_y = -d2*d4
        Q_theta = (
                (1/2)*A1*CD*b*d10*d6*rho1*sin_theta - A1*d10*d3*d7*d9*rho1 + (1/2)*A2*CD*a*
                cos_theta*d15*d16*rho2 - A2*d11*d12*d16*d3*rho2)
        lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
        if lambda1 > l10:  # tether 1 taut: spring1, damper1
            t1_0 = b*sin_theta
            t1_1 = -delta_x + t1_0
            t1_2 = 1/lambda1
            t1_3 = -1 + lambda1/l10
            t1_4 = E1*t1_3
            t1_5 = t1_2*t1_4
            t1_6 = t1_1*t1_5
            t1_7 = b*cos_theta
            t1_8 = (
                    max(-t1_4, c1*(b*delta_y*sin_theta*t1_2*theta_dot + delta_x*delta_x_dot*t1_2 -
                    delta_x*t1_2*t1_7*theta_dot - delta_x_dot*t1_0*t1_2 + delta_y*delta_y_dot*t1_2 -
                    delta_y_dot*t1_2*t1_7)))
            t1_9 = t1_2*t1_8
            t1_10 = t1_1*t1_9
            t1_11 = -delta_y + t1_7
            Q_delta_x += t1_10 + t1_6
            Q_delta_y += t1_11*t1_5 + t1_11*t1_9
            Q_theta += E1*b*sin_theta*t1_11*t1_2*t1_3 + b*sin_theta*t1_11*t1_2*t1_8 - t1_10*t1_7 - t1_6*t1_7
        lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
        if lambda2 > l20:  # tether 2 taut: spring2, damper2
            t2_0 = a*sin_theta
            t2_1 = -delta_x - t2_0
            t2_2 = 1/lambda2
            t2_3 = E2*(-1 + lambda2/l20)
            t2_4 = t2_2*t2_3
            t2_5 = t2_1*t2_4
            t2_6 = delta_x_dot*t2_2
            t2_7 = delta_y_dot*t2_2
            t2_8 = a*cos_theta
            t2_9 = t2_2*theta_dot
            t2_10 = (
                    t2_2*max(-t2_3, c2*(delta_x*t2_6 + delta_x*t2_8*t2_9 - delta_y*t2_0*t2_9 +
                    delta_y*t2_7 + t2_0*t2_6 + t2_7*t2_8)))
            t2_11 = t2_1*t2_10
            t2_12 = -delta_y - t2_8
            t2_13 = t2_12*t2_4
            t2_14 = t2_10*t2_12
            Q_delta_x += t2_11 + t2_5
            Q_delta_y += t2_13 + t2_14
            Q_theta += -t2_0*t2_13 - t2_0*t2_14 + t2_11*t2_8 + t2_5*t2_8
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
        # drag1: air drag on the tip-mass (3.32-3.34)
        f0_0 = b*sin_theta
        f0_1 = b*omega*sin_theta - f0_0*omega_earth - f0_0*theta_dot
        f0_2 = b*cos_theta
        f0_3 = f0_2 + r0
        f0_4 = f0_2*theta_dot - f0_3*omega + f0_3*omega_earth
        f0_5 = math.sqrt(f0_1**2 + f0_4**2)
        out[0*LANES + k] = 0
        out[1*LANES + k] = 0
        out[2*LANES + k] = (1/2)*A1*CD*b*f0_1*f0_5*rho1*sin_theta - 1/2*A1*CD*f0_2*f0_4*f0_5*rho1
        # drag2: air drag on the main bus (3.32-3.34)
        f1_0 = a*sin_theta
        f1_1 = -f1_0*omega + f1_0*omega_earth + f1_0*theta_dot
        f1_2 = a*cos_theta
        f1_3 = -f1_2 + r0
        f1_4 = -f1_2*theta_dot - f1_3*omega + f1_3*omega_earth
        f1_5 = (1/2)*A2*CD*rho2*math.sqrt(f1_1**2 + f1_4**2)
        out[3*LANES + k] = 0
        out[4*LANES + k] = 0
        out[5*LANES + k] = -f1_0*f1_1*f1_5 + f1_2*f1_4*f1_5
        # drag3: air drag on the balloon (3.32-3.34)
        f2_0 = delta_y + r0
        f2_1 = delta_x_dot - f2_0*omega + f2_0*omega_earth
        f2_2 = delta_x*omega - delta_x*omega_earth + delta_y_dot
        f2_3 = (1/2)*A3*CD*rho3*math.sqrt(f2_1**2 + f2_2**2)
        out[6*LANES + k] = -f2_1*f2_3
        out[7*LANES + k] = -f2_2*f2_3
        out[8*LANES + k] = 0
        # spring1: tension of tether 1 (3.35-3.42)
        if lambda1 > l10:
            f3_0 = 1/lambda1
            f3_1 = -1 + lambda1/l10
            f3_2 = E1*f3_0*f3_1
            f3_3 = f3_2*(b*sin_theta - delta_x)
            f3_4 = b*cos_theta
            f3_5 = -delta_y + f3_4
            out[9*LANES + k] = f3_3
            out[10*LANES + k] = f3_2*f3_5
            out[11*LANES + k] = E1*b*f3_0*f3_1*f3_5*sin_theta - f3_3*f3_4
        # spring2: tension of tether 2 (3.36-3.42)
        if lambda2 > l20:
            f4_0 = a*sin_theta
            f4_1 = E2*(-1 + lambda2/l20)/lambda2
            f4_2 = f4_1*(-delta_x - f4_0)
            f4_3 = a*cos_theta
            f4_4 = f4_1*(-delta_y - f4_3)
            out[12*LANES + k] = f4_2
            out[13*LANES + k] = f4_4
            out[14*LANES + k] = -f4_0*f4_4 + f4_2*f4_3
        # damper1: damping of tether 1 along its stretch rate (variant (issue 5))
        if lambda1 > l10:
            f5_0 = b*sin_theta
            f5_1 = 1/lambda1
            f5_2 = b*cos_theta
            f5_3 = (
                    max(-E1*(-1 + lambda1/l10), c1*(b*delta_y*f5_1*sin_theta*theta_dot + delta_x*
                    delta_x_dot*f5_1 - delta_x*f5_1*f5_2*theta_dot - delta_x_dot*f5_0*f5_1 + delta_y*
                    delta_y_dot*f5_1 - delta_y_dot*f5_1*f5_2)))
            f5_4 = f5_1*f5_3
            f5_5 = f5_4*(-delta_x + f5_0)
            f5_6 = -delta_y + f5_2
            out[15*LANES + k] = f5_5
            out[16*LANES + k] = f5_4*f5_6
            out[17*LANES + k] = b*f5_1*f5_3*f5_6*sin_theta - f5_2*f5_5
        # damper2: damping of tether 2 along its stretch rate (variant (issue 5))
        if lambda2 > l20:
            f6_0 = a*sin_theta
            f6_1 = 1/lambda2
            f6_2 = delta_x_dot*f6_1
            f6_3 = delta_y_dot*f6_1
            f6_4 = a*cos_theta
            f6_5 = f6_1*theta_dot
            f6_6 = (
                    f6_1*max(-E2*(-1 + lambda2/l20), c2*(delta_x*f6_2 + delta_x*f6_4*f6_5 - delta_y*
                    f6_0*f6_5 + delta_y*f6_3 + f6_0*f6_2 + f6_3*f6_4)))
            f6_7 = f6_6*(-delta_x - f6_0)
            f6_8 = f6_6*(-delta_y - f6_4)
            out[18*LANES + k] = f6_7
            out[19*LANES + k] = f6_8
            out[20*LANES + k] = -f6_0*f6_8 + f6_4*f6_7


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
    # drag1: air drag on the tip-mass (3.32-3.34)
    f0_0 = b*sin_theta
    f0_1 = b*omega*sin_theta - f0_0*omega_earth - f0_0*theta_dot
    f0_2 = b*cos_theta
    f0_3 = f0_2 + r0
    f0_4 = f0_2*theta_dot - f0_3*omega + f0_3*omega_earth
    f0_5 = math.sqrt(f0_1**2 + f0_4**2)
    out[0, 0] = 0
    out[0, 1] = 0
    out[0, 2] = (1/2)*A1*CD*b*f0_1*f0_5*rho1*sin_theta - 1/2*A1*CD*f0_2*f0_4*f0_5*rho1
    # drag2: air drag on the main bus (3.32-3.34)
    f1_0 = a*sin_theta
    f1_1 = -f1_0*omega + f1_0*omega_earth + f1_0*theta_dot
    f1_2 = a*cos_theta
    f1_3 = -f1_2 + r0
    f1_4 = -f1_2*theta_dot - f1_3*omega + f1_3*omega_earth
    f1_5 = (1/2)*A2*CD*rho2*math.sqrt(f1_1**2 + f1_4**2)
    out[1, 0] = 0
    out[1, 1] = 0
    out[1, 2] = -f1_0*f1_1*f1_5 + f1_2*f1_4*f1_5
    # drag3: air drag on the balloon (3.32-3.34)
    f2_0 = delta_y + r0
    f2_1 = delta_x_dot - f2_0*omega + f2_0*omega_earth
    f2_2 = delta_x*omega - delta_x*omega_earth + delta_y_dot
    f2_3 = (1/2)*A3*CD*rho3*math.sqrt(f2_1**2 + f2_2**2)
    out[2, 0] = -f2_1*f2_3
    out[2, 1] = -f2_2*f2_3
    out[2, 2] = 0
    # spring1: tension of tether 1 (3.35-3.42)
    if lambda1 > l10:
        f3_0 = 1/lambda1
        f3_1 = -1 + lambda1/l10
        f3_2 = E1*f3_0*f3_1
        f3_3 = f3_2*(b*sin_theta - delta_x)
        f3_4 = b*cos_theta
        f3_5 = -delta_y + f3_4
        out[3, 0] = f3_3
        out[3, 1] = f3_2*f3_5
        out[3, 2] = E1*b*f3_0*f3_1*f3_5*sin_theta - f3_3*f3_4
    # spring2: tension of tether 2 (3.36-3.42)
    if lambda2 > l20:
        f4_0 = a*sin_theta
        f4_1 = E2*(-1 + lambda2/l20)/lambda2
        f4_2 = f4_1*(-delta_x - f4_0)
        f4_3 = a*cos_theta
        f4_4 = f4_1*(-delta_y - f4_3)
        out[4, 0] = f4_2
        out[4, 1] = f4_4
        out[4, 2] = -f4_0*f4_4 + f4_2*f4_3
    # damper1: damping of tether 1 along its stretch rate (variant (issue 5))
    if lambda1 > l10:
        f5_0 = b*sin_theta
        f5_1 = 1/lambda1
        f5_2 = b*cos_theta
        f5_3 = (
                max(-E1*(-1 + lambda1/l10), c1*(b*delta_y*f5_1*sin_theta*theta_dot + delta_x*
                delta_x_dot*f5_1 - delta_x*f5_1*f5_2*theta_dot - delta_x_dot*f5_0*f5_1 + delta_y*
                delta_y_dot*f5_1 - delta_y_dot*f5_1*f5_2)))
        f5_4 = f5_1*f5_3
        f5_5 = f5_4*(-delta_x + f5_0)
        f5_6 = -delta_y + f5_2
        out[5, 0] = f5_5
        out[5, 1] = f5_4*f5_6
        out[5, 2] = b*f5_1*f5_3*f5_6*sin_theta - f5_2*f5_5
    # damper2: damping of tether 2 along its stretch rate (variant (issue 5))
    if lambda2 > l20:
        f6_0 = a*sin_theta
        f6_1 = 1/lambda2
        f6_2 = delta_x_dot*f6_1
        f6_3 = delta_y_dot*f6_1
        f6_4 = a*cos_theta
        f6_5 = f6_1*theta_dot
        f6_6 = (
                f6_1*max(-E2*(-1 + lambda2/l20), c2*(delta_x*f6_2 + delta_x*f6_4*f6_5 - delta_y*f6_0*
                f6_5 + delta_y*f6_3 + f6_0*f6_2 + f6_3*f6_4)))
        f6_7 = f6_6*(-delta_x - f6_0)
        f6_8 = f6_6*(-delta_y - f6_4)
        out[6, 0] = f6_7
        out[6, 1] = f6_8
        out[6, 2] = -f6_0*f6_8 + f6_4*f6_7


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
    e0 = (1/2)*m3
    e1 = (3/2)*omega**2
    e2 = e1*m3
    e3 = a**2*m2
    e4 = cos_theta**2
    e5 = e1*e4
    e6 = (1/2)*theta_dot**2
    e7 = e4*e6
    e8 = sin_theta**2
    e9 = e6*e8
    e10 = b**2*m1
    e11 = 1/r0
    e12 = e11*e2
    e13 = e1*e11
    e14 = cos_theta**3*e13
    e15 = a**3*m2
    e16 = b**3*m1
    e17 = cos_theta*e13*e8
    h = (
            -delta_x**2*delta_y*e12 + delta_x_dot**2*e0 - delta_y**3*e12 - delta_y**2*e2 +
            delta_y_dot**2*e0 - e10*e5 + e10*e7 + e10*e9 + e14*e15 - e14*e16 + e15*e17 - e16*e17 -
            e3*e5 + e3*e7 + e3*e9)
    lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
    if lambda1 > l10:
        h += (1/2)*E1*(-l10 + lambda1)**2/l10
    lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
    if lambda2 > l20:
        h += (1/2)*E2*(-l20 + lambda2)**2/l20
    return h


@njit(cache=True)
def jacobian(t, y, p, J):
    """J[i, j] = ∂(dy_i/dt)/∂y_j of model 'objective-damper' (units of y_i/s per y_j)."""
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
    jd21 = b*cos_theta
    jd22 = jd21*theta_dot
    jd23 = b*sin_theta
    jd24 = jd23*theta_dot
    jd25 = b*omega*sin_theta - jd23*omega_earth - jd24
    jd26 = jd21 + r0
    jd27 = jd22 - jd26*omega + jd26*omega_earth
    jd28 = math.sqrt(jd25**2 + jd27**2)
    jd29 = a*cos_theta
    jd30 = jd29*theta_dot
    jd31 = a*sin_theta
    jd32 = jd31*theta_dot
    jd33 = -jd31*omega + jd31*omega_earth + jd32
    jd34 = -jd29 + r0
    jd35 = -jd30 - jd34*omega + jd34*omega_earth
    jd36 = math.sqrt(jd33**2 + jd35**2)
    jd37 = A2*rho2
    jd38 = jd36*jd37
    jd39 = jd31*jd38
    jd40 = (1/2)*jd35
    jd41 = 1/jd28
    jd42 = (1/2)*jd27
    jd43 = (
            (1/2)*jd25*(2*b*cos_theta*omega - jd21*jd5 - 2*jd22) + jd42*(2*b*omega*sin_theta -
            jd23*jd5 - 2*jd24))
    jd44 = (1/2)*jd33
    jd45 = jd40*(-jd31*jd4 + jd31*jd5 + 2*jd32) + jd44*(-jd29*jd4 + jd29*jd5 + 2*jd30)
    jd46 = 1/jd36
    jd47 = jd37*jd46
    jd48 = CD*jd31*jd44
    jd49 = A1*rho1
    jd50 = jd41*jd49
    jd51 = CD*jd21*jd42
    jd52 = cos_theta**2*jd15
    jd53 = b**2*jd28*jd49
    jd54 = jd15*sin_theta**2
    jd55 = a**2*jd38
    jd56 = jd21*jd27 - jd23*jd25
    jd57 = a*jd33*sin_theta - jd29*jd35
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
            (1/2)*A1*CD*b*jd25*jd41*jd43*rho1*sin_theta + (1/2)*A1*CD*b*jd27*jd28*rho1*
            sin_theta + (1/2)*A1*CD*b*jd28*rho1*sin_theta*(b*cos_theta*omega - jd21*omega_earth -
            jd22) + (1/2)*A2*CD*a*cos_theta*jd35*jd45*jd46*rho2 - CD*jd39*jd40 - jd15*jd39*
            (-jd29*omega + jd29*omega_earth + jd30) - jd43*jd50*jd51 - jd45*jd47*jd48)
    dQ2_3 = 0
    dQ2_4 = 0
    dQ2_5 = (
            (1/2)*A1*CD*b*jd25*jd41*jd56*rho1*sin_theta + (1/2)*A2*CD*a*cos_theta*jd35*jd46*
            jd57*rho2 - jd47*jd48*jd57 - jd50*jd51*jd56 - jd52*jd53 - jd52*jd55 - jd53*jd54 - jd54*
            jd55)
    lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
    if lambda1 > l10:
        jt1_0 = b*sin_theta
        jt1_1 = -delta_x + jt1_0
        jt1_2 = jt1_1**2
        jt1_3 = 1/l10
        jt1_4 = jt1_3*lambda1 - 1
        jt1_5 = E1*jt1_4
        jt1_6 = b*cos_theta
        jt1_7 = -delta_y + jt1_6
        jt1_8 = jt1_7**2
        jt1_9 = jt1_2 + jt1_8
        jt1_10 = 1/math.sqrt(jt1_9)
        jt1_11 = delta_y_dot*jt1_10
        jt1_12 = delta_x_dot*jt1_10
        jt1_13 = delta_x*jt1_10
        jt1_14 = jt1_13*jt1_6
        jt1_15 = (
                c1*(b*delta_y*jt1_10*sin_theta*theta_dot + delta_x*delta_x_dot*jt1_10 + delta_y*
                delta_y_dot*jt1_10 - jt1_0*jt1_12 - jt1_11*jt1_6 - jt1_14*theta_dot))
        jt1_16 = max(jt1_15, -jt1_5)
        jt1_17 = jt1_9**(-3/2)
        jt1_18 = jt1_16*jt1_17
        jt1_19 = jt1_18*jt1_2
        jt1_20 = E1*jt1_3
        jt1_21 = -jt1_1*jt1_20
        jt1_22 = jt1_15 + jt1_5
        jt1_23 = jt1_10*(1.0 if -jt1_22 > 0.0 else 0.5 if -jt1_22 == 0.0 else 0.0)
        jt1_24 = (1.0 if jt1_22 > 0.0 else 0.5 if jt1_22 == 0.0 else 0.0)
        jt1_25 = jt1_10*jt1_6
        jt1_26 = jt1_1*jt1_6
        jt1_27 = jt1_17*jt1_26
        jt1_28 = jt1_1*jt1_17
        jt1_29 = delta_x_dot*jt1_0
        jt1_30 = (
                c1*jt1_24*(b*delta_y*jt1_1*jt1_17*sin_theta*theta_dot + delta_x*delta_x_dot*jt1_1*
                jt1_17 - delta_x*jt1_27*theta_dot + delta_x_dot*jt1_10 + delta_y*delta_y_dot*jt1_1*
                jt1_17 - delta_y_dot*jt1_27 - jt1_25*theta_dot - jt1_28*jt1_29) - jt1_21*jt1_23)
        jt1_31 = jt1_1*jt1_10
        jt1_32 = jt1_30*jt1_31
        jt1_33 = jt1_17*jt1_5
        jt1_34 = jt1_2*jt1_33
        jt1_35 = 1/jt1_9
        jt1_36 = jt1_1*jt1_35
        jt1_37 = jt1_10*jt1_16
        jt1_38 = jt1_10*jt1_5
        jt1_39 = -jt1_37 - jt1_38
        jt1_40 = -jt1_7
        jt1_41 = jt1_20*jt1_40
        jt1_42 = jt1_0*jt1_10
        jt1_43 = delta_x*delta_x_dot
        jt1_44 = jt1_17*jt1_7
        jt1_45 = delta_y*delta_y_dot
        jt1_46 = delta_y_dot*jt1_6
        jt1_47 = jt1_0*jt1_7
        jt1_48 = jt1_17*jt1_47
        jt1_49 = jt1_6*theta_dot
        jt1_50 = delta_x*jt1_49
        jt1_51 = (
                c1*jt1_24*(-delta_x_dot*jt1_48 + delta_y*jt1_48*theta_dot + jt1_11 + jt1_42*theta_dot +
                jt1_43*jt1_44 + jt1_44*jt1_45 - jt1_44*jt1_46 - jt1_44*jt1_50) - jt1_23*jt1_41)
        jt1_52 = jt1_31*jt1_51
        jt1_53 = jt1_1*jt1_18
        jt1_54 = jt1_28*jt1_5
        jt1_55 = jt1_53*jt1_7 + jt1_54*jt1_7
        jt1_56 = -b*jt1_7*sin_theta + jt1_26
        jt1_57 = jt1_20*jt1_56
        jt1_58 = jt1_0*theta_dot
        jt1_59 = -jt1_56
        jt1_60 = jt1_17*jt1_59
        jt1_61 = (
                c1*jt1_24*(delta_y*jt1_10*jt1_49 + delta_y*jt1_58*jt1_60 + jt1_0*jt1_11 - jt1_12*
                jt1_6 + jt1_13*jt1_58 - jt1_29*jt1_60 + jt1_43*jt1_60 + jt1_45*jt1_60 - jt1_46*jt1_60 -
                jt1_50*jt1_60) - jt1_23*jt1_57)
        jt1_62 = jt1_31*jt1_61
        jt1_63 = jt1_37*jt1_6 + jt1_38*jt1_6
        jt1_64 = delta_x*jt1_10 - jt1_42
        jt1_65 = c1*jt1_24
        jt1_66 = jt1_31*jt1_65
        jt1_67 = jt1_64*jt1_66
        jt1_68 = delta_y*jt1_10 - jt1_25
        jt1_69 = jt1_66*jt1_68
        jt1_70 = b*delta_y*jt1_10*sin_theta - jt1_14
        jt1_71 = jt1_66*jt1_70
        jt1_72 = jt1_10*jt1_7
        jt1_73 = jt1_35*jt1_7
        jt1_74 = jt1_0*jt1_38
        jt1_75 = jt1_59*jt1_7
        jt1_76 = jt1_0*jt1_37
        jt1_77 = jt1_65*jt1_72
        jt1_78 = jt1_21*jt1_35
        jt1_79 = jt1_26*jt1_33
        jt1_80 = jt1_18*jt1_26
        jt1_81 = cos_theta**2
        jt1_82 = b**2
        jt1_83 = jt1_38*jt1_82
        jt1_84 = sin_theta**2
        jt1_85 = jt1_37*jt1_82
        dQ0_0 += jt1_19 + jt1_21*jt1_36 + jt1_32 + jt1_34 + jt1_39
        dQ0_1 += jt1_36*jt1_41 + jt1_52 + jt1_55
        dQ0_2 += jt1_36*jt1_57 + jt1_53*jt1_59 + jt1_54*jt1_59 + jt1_62 + jt1_63
        dQ0_3 += jt1_67
        dQ0_4 += jt1_69
        dQ0_5 += jt1_71
        dQ1_0 += jt1_21*jt1_73 + jt1_30*jt1_72 + jt1_55
        dQ1_1 += jt1_18*jt1_8 + jt1_33*jt1_8 + jt1_39 + jt1_41*jt1_73 + jt1_51*jt1_72
        dQ1_2 += jt1_18*jt1_75 + jt1_33*jt1_75 + jt1_57*jt1_73 + jt1_61*jt1_72 - jt1_74 - jt1_76
        dQ1_3 += jt1_64*jt1_77
        dQ1_4 += jt1_68*jt1_77
        dQ1_5 += jt1_70*jt1_77
        dQ2_0 += (
                jt1_10*jt1_30*jt1_47 - jt1_19*jt1_6 - jt1_26*jt1_78 - jt1_32*jt1_6 - jt1_34*jt1_6 +
                jt1_47*jt1_53 + jt1_47*jt1_54 + jt1_47*jt1_78 + jt1_63)
        dQ2_1 += (
                E1*b*jt1_17*jt1_4*jt1_8*sin_theta + E1*b*jt1_3*jt1_35*jt1_40*jt1_7*sin_theta + b*
                jt1_10*jt1_51*jt1_7*sin_theta + b*jt1_16*jt1_17*jt1_8*sin_theta - jt1_26*jt1_35*
                jt1_41 - jt1_52*jt1_6 - jt1_7*jt1_79 - jt1_7*jt1_80 - jt1_74 - jt1_76)
        dQ2_2 += (
                E1*b*cos_theta*jt1_10*jt1_4*jt1_7 + E1*b*jt1_1*jt1_10*jt1_4*sin_theta + E1*b*
                jt1_17*jt1_4*jt1_59*jt1_7*sin_theta + E1*b*jt1_3*jt1_35*jt1_56*jt1_7*sin_theta + b*
                cos_theta*jt1_10*jt1_16*jt1_7 + b*jt1_1*jt1_10*jt1_16*sin_theta + b*jt1_10*jt1_61*
                jt1_7*sin_theta + b*jt1_16*jt1_17*jt1_59*jt1_7*sin_theta - jt1_26*jt1_35*jt1_57 -
                jt1_59*jt1_79 - jt1_59*jt1_80 - jt1_6*jt1_62 - jt1_81*jt1_83 - jt1_81*jt1_85 - jt1_83*
                jt1_84 - jt1_84*jt1_85)
        dQ2_3 += b*c1*jt1_10*jt1_24*jt1_64*jt1_7*sin_theta - jt1_6*jt1_67
        dQ2_4 += b*c1*jt1_10*jt1_24*jt1_68*jt1_7*sin_theta - jt1_6*jt1_69
        dQ2_5 += b*c1*jt1_10*jt1_24*jt1_7*jt1_70*sin_theta - jt1_6*jt1_71
    lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
    if lambda2 > l20:
        jt2_0 = a*sin_theta
        jt2_1 = delta_x + jt2_0
        jt2_2 = -jt2_1
        jt2_3 = jt2_2**2
        jt2_4 = 1/l20
        jt2_5 = jt2_4*lambda2 - 1
        jt2_6 = E2*jt2_5
        jt2_7 = a*cos_theta
        jt2_8 = delta_y + jt2_7
        jt2_9 = -jt2_8
        jt2_10 = jt2_9**2
        jt2_11 = jt2_10 + jt2_3
        jt2_12 = 1/math.sqrt(jt2_11)
        jt2_13 = delta_x_dot*jt2_12
        jt2_14 = delta_y_dot*jt2_12
        jt2_15 = delta_x*jt2_12
        jt2_16 = jt2_15*jt2_7
        jt2_17 = delta_y*jt2_12
        jt2_18 = jt2_0*jt2_17
        jt2_19 = (
                c2*(delta_x*jt2_13 + delta_y*jt2_14 + jt2_0*jt2_13 + jt2_14*jt2_7 + jt2_16*theta_dot -
                jt2_18*theta_dot))
        jt2_20 = max(jt2_19, -jt2_6)
        jt2_21 = jt2_11**(-3/2)
        jt2_22 = jt2_20*jt2_21
        jt2_23 = E2*jt2_4
        jt2_24 = jt2_1*jt2_23
        jt2_25 = jt2_19 + jt2_6
        jt2_26 = jt2_12*(1.0 if -jt2_25 > 0.0 else 0.5 if -jt2_25 == 0.0 else 0.0)
        jt2_27 = (1.0 if jt2_25 > 0.0 else 0.5 if jt2_25 == 0.0 else 0.0)
        jt2_28 = jt2_12*jt2_7
        jt2_29 = jt2_2*jt2_21
        jt2_30 = delta_x*delta_x_dot
        jt2_31 = delta_y*delta_y_dot
        jt2_32 = jt2_2*jt2_7
        jt2_33 = jt2_21*jt2_32
        jt2_34 = delta_x_dot*jt2_0
        jt2_35 = jt2_0*theta_dot
        jt2_36 = delta_y*jt2_35
        jt2_37 = (
                c2*jt2_27*(delta_x*jt2_33*theta_dot + delta_y_dot*jt2_33 + jt2_13 + jt2_28*theta_dot +
                jt2_29*jt2_30 + jt2_29*jt2_31 + jt2_29*jt2_34 - jt2_29*jt2_36) - jt2_24*jt2_26)
        jt2_38 = jt2_12*jt2_2
        jt2_39 = jt2_21*jt2_6
        jt2_40 = 1/jt2_11
        jt2_41 = jt2_2*jt2_40
        jt2_42 = jt2_12*jt2_20
        jt2_43 = jt2_12*jt2_6
        jt2_44 = -jt2_42 - jt2_43
        jt2_45 = jt2_23*jt2_8
        jt2_46 = jt2_0*jt2_12
        jt2_47 = jt2_21*jt2_9
        jt2_48 = delta_y_dot*jt2_7
        jt2_49 = jt2_0*jt2_9
        jt2_50 = jt2_21*jt2_49
        jt2_51 = jt2_7*theta_dot
        jt2_52 = delta_x*jt2_51
        jt2_53 = (
                c2*jt2_27*(delta_x_dot*jt2_50 - delta_y*jt2_50*theta_dot + jt2_14 + jt2_30*jt2_47 +
                jt2_31*jt2_47 - jt2_46*theta_dot + jt2_47*jt2_48 + jt2_47*jt2_52) - jt2_26*jt2_45)
        jt2_54 = jt2_38*jt2_53
        jt2_55 = jt2_2*jt2_22
        jt2_56 = jt2_29*jt2_6
        jt2_57 = jt2_55*jt2_9 + jt2_56*jt2_9
        jt2_58 = jt2_43*jt2_7
        jt2_59 = jt2_32 - jt2_49
        jt2_60 = -jt2_59
        jt2_61 = jt2_23*jt2_60
        jt2_62 = jt2_42*jt2_7
        jt2_63 = jt2_21*jt2_59
        jt2_64 = (
                c2*jt2_27*(-jt2_0*jt2_14 + jt2_13*jt2_7 - jt2_15*jt2_35 - jt2_17*jt2_51 + jt2_30*
                jt2_63 + jt2_31*jt2_63 + jt2_34*jt2_63 - jt2_36*jt2_63 + jt2_48*jt2_63 + jt2_52*jt2_63)
                - jt2_26*jt2_61)
        jt2_65 = jt2_15 + jt2_46
        jt2_66 = c2*jt2_27
        jt2_67 = jt2_38*jt2_66
        jt2_68 = jt2_65*jt2_67
        jt2_69 = jt2_17 + jt2_28
        jt2_70 = jt2_67*jt2_69
        jt2_71 = jt2_16 - jt2_18
        jt2_72 = jt2_67*jt2_71
        jt2_73 = jt2_12*jt2_9
        jt2_74 = jt2_40*jt2_9
        jt2_75 = jt2_10*jt2_22
        jt2_76 = jt2_10*jt2_39
        jt2_77 = jt2_59*jt2_9
        jt2_78 = jt2_0*jt2_42
        jt2_79 = jt2_0*jt2_43 + jt2_78
        jt2_80 = jt2_66*jt2_73
        jt2_81 = jt2_12*jt2_49
        jt2_82 = jt2_40*jt2_45
        jt2_83 = cos_theta**2
        jt2_84 = a**2
        jt2_85 = jt2_43*jt2_84
        jt2_86 = sin_theta**2
        jt2_87 = jt2_49*jt2_59
        jt2_88 = jt2_42*jt2_84
        jt2_89 = jt2_66*jt2_81
        dQ0_0 += jt2_22*jt2_3 + jt2_24*jt2_41 + jt2_3*jt2_39 + jt2_37*jt2_38 + jt2_44
        dQ0_1 += jt2_41*jt2_45 + jt2_54 + jt2_57
        dQ0_2 += jt2_38*jt2_64 + jt2_41*jt2_61 + jt2_55*jt2_59 + jt2_56*jt2_59 - jt2_58 - jt2_62
        dQ0_3 += jt2_68
        dQ0_4 += jt2_70
        dQ0_5 += jt2_72
        dQ1_0 += jt2_24*jt2_74 + jt2_37*jt2_73 + jt2_57
        dQ1_1 += jt2_44 + jt2_45*jt2_74 + jt2_53*jt2_73 + jt2_75 + jt2_76
        dQ1_2 += jt2_22*jt2_77 + jt2_39*jt2_77 + jt2_61*jt2_74 + jt2_64*jt2_73 + jt2_79
        dQ1_3 += jt2_65*jt2_80
        dQ1_4 += jt2_69*jt2_80
        dQ1_5 += jt2_71*jt2_80
        dQ2_0 += (
                E2*a*cos_theta*jt2_1*jt2_2*jt2_4*jt2_40 + E2*a*cos_theta*jt2_21*jt2_3*jt2_5 + a*
                cos_theta*jt2_12*jt2_2*jt2_37 + a*cos_theta*jt2_20*jt2_21*jt2_3 - jt2_24*jt2_40*
                jt2_49 - jt2_37*jt2_81 - jt2_49*jt2_55 - jt2_49*jt2_56 - jt2_58 - jt2_62)
        dQ2_1 += (
                -jt2_0*jt2_75 - jt2_0*jt2_76 + jt2_22*jt2_32*jt2_9 + jt2_32*jt2_39*jt2_9 + jt2_32*
                jt2_82 - jt2_49*jt2_82 - jt2_53*jt2_81 + jt2_54*jt2_7 + jt2_79)
        dQ2_2 += (
                E2*a*cos_theta*jt2_2*jt2_21*jt2_5*jt2_59 + E2*a*cos_theta*jt2_2*jt2_4*jt2_40*
                jt2_60 + a*cos_theta*jt2_12*jt2_2*jt2_64 + a*cos_theta*jt2_2*jt2_20*jt2_21*jt2_59 -
                jt2_0*jt2_38*jt2_6 - jt2_2*jt2_78 - jt2_22*jt2_87 - jt2_39*jt2_87 - jt2_40*jt2_49*
                jt2_61 - jt2_58*jt2_9 - jt2_62*jt2_9 - jt2_64*jt2_81 - jt2_83*jt2_85 - jt2_83*jt2_88 -
                jt2_85*jt2_86 - jt2_86*jt2_88)
        dQ2_3 += -jt2_65*jt2_89 + jt2_68*jt2_7
        dQ2_4 += -jt2_69*jt2_89 + jt2_7*jt2_70
        dQ2_5 += jt2_7*jt2_72 - jt2_71*jt2_89
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
