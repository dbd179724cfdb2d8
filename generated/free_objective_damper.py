"""GENERATED FILE - DO NOT EDIT.

Model 'free-objective-damper': free orbit (r, nu as coordinates), truncated binomial gravity, Kelvin-Voigt
tether dampers.
Produced by `make derive` (python -m derive) from derive/orbit.py and
derive/orbit_codegen.py; regenerate instead of editing.  sympy 1.14.0.
Reduces to the model 'objective-damper' on a circular orbit.

State vector y (index, name, unit):
   0  delta_x      m
   1  delta_y      m
   2  theta        rad
   3  r            m
   4  nu           rad
   5  delta_x_dot  m/s
   6  delta_y_dot  m/s
   7  theta_dot    rad/s
   8  r_dot        m/s
   9  nu_dot       rad/s

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
  15  mu           m^3/s^2   Earth's gravitational parameter
  16  omega_earth  rad/s     Earth's rotation rate (atmosphere co-rotates)
  17  rho1         kg/m^3    air density at the tip-mass
  18  rho2         kg/m^3    air density at the main bus
  19  rho3         kg/m^3    air density at the balloon
  20  J2           1         Earth's second zonal harmonic (0 switches J2 off)
  21  R_E          m         Earth's equatorial radius (J2 term)
"""
import math

from numba import njit

from .trig import sincos

MODEL = 'free-objective-damper'
DESCRIPTION = 'free orbit (r, nu as coordinates), truncated binomial gravity, Kelvin-Voigt tether dampers'
GEOMETRY = "planar"  # (δx, δy, θ) in the orbit plane
ORBIT = "free"  # r and ν are coordinates: gravity, J2 and drag move the orbit
CIRCULAR_TWIN = 'objective-damper'  # the model this one reduces to on a circular orbit
FAMILIES = ('drag1', 'drag2', 'drag3', 'spring1', 'spring2', 'damper1', 'damper2')
STATE = (
    'delta_x', 'delta_y', 'theta', 'r', 'nu', 'delta_x_dot', 'delta_y_dot', 'theta_dot', 'r_dot', 'nu_dot',
)
STATE_UNITS = ('m', 'm', 'rad', 'm', 'rad', 'm/s', 'm/s', 'rad/s', 'm/s', 'rad/s')
PARAMETERS = (
    'm1', 'm2', 'm3', 'A1', 'A2', 'A3', 'a', 'b', 'l10', 'l20', 'E1', 'E2', 'c1', 'c2', 'CD', 'mu',
    'omega_earth', 'rho1', 'rho2', 'rho3', 'J2', 'R_E',
)
PARAMETER_UNITS = (
    'kg', 'kg', 'kg', 'm^2', 'm^2', 'm^2', 'm', 'm', 'm', 'm', 'N', 'N', 'N s/m', 'N s/m', '1', 'm^3/s^2',
    'rad/s', 'kg/m^3', 'kg/m^3', 'kg/m^3', '1', 'm',
)

Y_DELTA_X = 0
Y_DELTA_Y = 1
Y_THETA = 2
Y_R = 3
Y_NU = 4
Y_DELTA_X_DOT = 5
Y_DELTA_Y_DOT = 6
Y_THETA_DOT = 7
Y_R_DOT = 8
Y_NU_DOT = 9

P_M1 = 0
P_M2 = 1
P_M3 = 2
P_A1 = 3
P_A2 = 4
P_A3 = 5
P_A = 6
P_B = 7
P_L10 = 8
P_L20 = 9
P_E1 = 10
P_E2 = 11
P_C1 = 12
P_C2 = 13
P_CD = 14
P_MU = 15
P_OMEGA_EARTH = 16
P_RHO1 = 17
P_RHO2 = 18
P_RHO3 = 19
P_J2 = 20
P_R_E = 21


@njit(cache=True)
def rhs(t, y, p, dydt):
    """State derivative dy/dt of model 'free-objective-damper' (SI; y, p as in STATE, PARAMETERS)."""
    delta_x = y[0]
    delta_y = y[1]
    theta = y[2]
    r = y[3]
    delta_x_dot = y[5]
    delta_y_dot = y[6]
    theta_dot = y[7]
    r_dot = y[8]
    nu_dot = y[9]
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
    mu = p[15]
    omega_earth = p[16]
    rho1 = p[17]
    rho2 = p[18]
    rho3 = p[19]
    J2 = p[20]
    R_E = p[21]
    sin_theta, cos_theta = sincos(theta)
    # air drag on the three bodies (3.32-3.34, co-rotating air)
    d0 = delta_y + r
    d1 = -d0*nu_dot + d0*omega_earth + delta_x_dot
    d2 = delta_x*nu_dot - delta_x*omega_earth + delta_y_dot + r_dot
    d3 = (1/2)*CD
    d4 = A3*d3*rho3*math.sqrt(d1**2 + d2**2)
    d5 = d1*d4
    d6 = d2*d4
    d7 = b*cos_theta
    d8 = d7 + r
    d9 = d7*theta_dot - d8*nu_dot + d8*omega_earth
    d10 = b*sin_theta
    d11 = d10*nu_dot - d10*omega_earth - d10*theta_dot + r_dot
    d12 = A1*d3*rho1*math.sqrt(d11**2 + d9**2)
    d13 = d12*d9
    d14 = a*cos_theta
    d15 = -d14 + r
    d16 = -d14*theta_dot - d15*nu_dot + d15*omega_earth
    d17 = a*sin_theta
    d18 = -d17*nu_dot + d17*omega_earth + d17*theta_dot + r_dot
    d19 = math.sqrt(d16**2 + d18**2)
    d20 = A2*d19*d3*rho2
    d21 = d18*d20
    d22 = d11*d12
    d23 = -d10*d22 + d17*d21
    Q_delta_x = -d5
    Q_delta_y = -d6
    Q_theta = (1/2)*A2*CD*a*cos_theta*d16*d19*rho2 - d13*d7 - d23
    Q_r = -d21 - d22 - d6
    Q_nu = d0*d5 + d13*d8 + d15*d16*d20 + d23 - d6*delta_x
    lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
    if lambda1 > l10:  # tether 1 taut: spring1, damper1
        t1_0 = 1/l10
        t1_1 = E1*delta_x
        t1_2 = 1/lambda1
        t1_3 = b*sin_theta
        t1_4 = E1*t1_2
        t1_5 = E1*t1_0
        t1_6 = c1*t1_2
        t1_7 = b*cos_theta
        t1_8 = t1_6*t1_7
        t1_9 = (
                max(E1 - lambda1*t1_5, b*c1*delta_y*sin_theta*t1_2*theta_dot + c1*delta_x*
                delta_x_dot*t1_2 + c1*delta_y*delta_y_dot*t1_2 - delta_x*t1_8*theta_dot - delta_x_dot*
                t1_3*t1_6 - delta_y_dot*t1_8))
        t1_10 = t1_2*t1_9
        t1_11 = delta_y*t1_5
        t1_12 = delta_y*t1_10
        Q_delta_x += (
                E1*b*sin_theta*t1_0 + E1*delta_x*t1_2 + b*sin_theta*t1_2*t1_9 - delta_x*t1_10 -
                t1_0*t1_1 - t1_3*t1_4)
        Q_delta_y += E1*b*cos_theta*t1_0 + E1*delta_y*t1_2 + b*cos_theta*t1_2*t1_9 - t1_11 - t1_12 - t1_4*t1_7
        Q_theta += (
                E1*b*cos_theta*delta_x*t1_0 + E1*b*delta_y*sin_theta*t1_2 + b*cos_theta*delta_x*
                t1_2*t1_9 - t1_1*t1_2*t1_7 - t1_11*t1_3 - t1_12*t1_3)
        Q_r += 0
        Q_nu += 0
    lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
    if lambda2 > l20:  # tether 2 taut: spring2, damper2
        t2_0 = 1/l20
        t2_1 = E2*delta_x
        t2_2 = t2_0*t2_1
        t2_3 = 1/lambda2
        t2_4 = E2*t2_0
        t2_5 = a*sin_theta
        t2_6 = c2*t2_3
        t2_7 = delta_x_dot*t2_6
        t2_8 = delta_y*t2_3
        t2_9 = c2*t2_8
        t2_10 = a*cos_theta
        t2_11 = t2_10*t2_6
        t2_12 = (
                t2_3*max(E2 - lambda2*t2_4, delta_x*t2_11*theta_dot + delta_x*t2_7 + delta_y_dot*t2_11
                + delta_y_dot*t2_9 + t2_5*t2_7 - t2_5*t2_9*theta_dot))
        t2_13 = delta_x*t2_12
        t2_14 = delta_y*t2_4
        t2_15 = delta_y*t2_12
        Q_delta_x += E2*a*sin_theta*t2_3 + E2*delta_x*t2_3 - t2_12*t2_5 - t2_13 - t2_2 - t2_4*t2_5
        Q_delta_y += E2*a*cos_theta*t2_3 + E2*delta_y*t2_3 - t2_10*t2_12 - t2_10*t2_4 - t2_14 - t2_15
        Q_theta += -E2*t2_5*t2_8 + t2_1*t2_10*t2_3 - t2_10*t2_13 - t2_10*t2_2 + t2_14*t2_5 + t2_15*t2_5
        Q_r += 0
        Q_nu += 0
    # M q'' = Q - f (Lagrange, Eq 3.26 with r, nu as coordinates)
    fb0 = 2*m3
    fb1 = fb0*nu_dot
    fb2 = delta_y_dot*fb1
    fb3 = fb1*r_dot
    fb4 = nu_dot**2
    fb5 = fb4*m3
    fb6 = r**(-3)
    fb7 = fb6*mu
    fb8 = delta_x*m3
    fb9 = r**(-4)
    fb10 = fb9*mu
    fb11 = 3*fb10
    fb12 = delta_y*fb8
    fb13 = r**(-5)
    fb14 = R_E**2
    fb15 = J2*fb14
    fb16 = fb15*mu
    fb17 = fb13*fb16
    fb18 = r**(-6)
    fb19 = fb16*fb18
    fb20 = delta_x_dot*fb1
    fb21 = r**(-2)
    fb22 = fb21*mu
    fb23 = fb22*m3
    fb24 = delta_x**2
    fb25 = m3*mu
    fb26 = fb25*fb9
    fb27 = (3/2)*fb26
    fb28 = delta_y**2
    fb29 = fb26*fb28
    fb30 = fb15*fb27
    fb31 = 6*fb13
    fb32 = delta_y*fb31
    fb33 = fb15*fb25
    fb34 = (15/4)*fb18
    fb35 = fb24*fb25
    fb36 = fb15*fb35
    fb37 = 15*fb18
    fb38 = fb28*fb33*fb37
    fb39 = a*m2
    fb40 = 2*nu_dot
    fb41 = fb40*r_dot
    fb42 = cos_theta*fb41
    fb43 = fb39*fb42
    fb44 = b*m1
    fb45 = fb42*fb44
    fb46 = fb22*m2
    fb47 = 3*fb7
    fb48 = a**2
    fb49 = fb48*m2
    fb50 = cos_theta*sin_theta
    fb51 = fb49*fb50
    fb52 = b**2
    fb53 = fb52*m1
    fb54 = fb50*fb53
    fb55 = a**3
    fb56 = sin_theta**3
    fb57 = b**3
    fb58 = fb57*m1
    fb59 = (3/2)*fb10
    fb60 = fb15*fb59
    fb61 = cos_theta**2
    fb62 = fb61*sin_theta
    fb63 = (15/2)*fb17
    fb64 = fb16*fb58
    fb65 = fb55*m2
    fb66 = theta_dot**2
    fb67 = fb40*theta_dot
    fb68 = cos_theta*fb39
    fb69 = delta_y**3
    fb70 = fb11*fb61
    fb71 = sin_theta**2
    fb72 = cos_theta**3
    fb73 = fb31*mu
    fb74 = r**(-7)
    fb75 = cos_theta*fb71
    fb76 = (45/2)*fb74
    fb77 = fb37*fb61
    fb78 = fb41*r
    fb79 = r*sin_theta
    B0 = Q_delta_x + delta_x*fb5 + fb11*fb12 + (15/2)*fb12*fb19 - 3/2*fb17*fb8 + fb2 + fb3 - fb7*fb8
    B1 = (
            Q_delta_y + delta_y*fb0*fb7 + delta_y*fb5 - fb20 - fb23 + fb24*fb27 + (9/2)*fb29 - fb30 +
            fb32*fb33 + fb34*fb36 - fb38 + fb5*r)
    B2 = (
            (3/2)*J2*b*fb14*fb9*m1*mu*sin_theta + (15/4)*J2*fb14*fb18*fb55*fb56*m2*mu + (45/2)*
            J2*fb14*fb18*fb57*fb61*m1*mu*sin_theta + Q_theta + a*fb4*m2*r*sin_theta - a*fb46*
            sin_theta + b*fb21*m1*mu*sin_theta - b*fb4*m1*r*sin_theta - 45/2*fb19*fb62*fb65 -
            fb34*fb56*fb64 - fb39*fb60*sin_theta - fb43 + fb45 - fb47*fb51 - fb47*fb54 - fb51*fb63 -
            fb54*fb63 + (3/2)*fb55*fb56*fb9*m2*mu + (3/2)*fb55*fb61*fb9*m2*mu*sin_theta - fb56*
            fb58*fb59 - fb58*fb59*fb62)
    B3 = (
            6*J2*b*cos_theta*fb13*fb14*m1*mu + (45/2)*J2*cos_theta*fb14*fb55*fb71*fb74*m2*mu +
            6*J2*delta_y*fb13*fb14*m3*mu + (15/4)*J2*fb14*fb18*fb24*m3*mu + (15/4)*J2*fb14*
            fb18*fb48*fb71*m2*mu + (15/4)*J2*fb14*fb18*fb52*fb71*m1*mu + 30*J2*fb14*fb57*fb72*
            fb74*m1*mu + 30*J2*fb14*fb69*fb74*m3*mu + Q_r + 2*a*cos_theta*m2*nu_dot*theta_dot +
            b*cos_theta*fb4*m1 + 2*b*cos_theta*fb6*m1*mu + b*cos_theta*fb66*m1 + 6*cos_theta*
            fb13*fb55*fb71*m2*mu - cos_theta*fb39*fb4 - cos_theta*fb39*fb66 - cos_theta*fb44*fb67 -
            delta_y*fb36*fb76 + delta_y*fb4*m3 + 2*delta_y*fb6*m3*mu + 6*fb13*fb55*fb72*m2*mu -
            fb15*fb68*fb73 - fb16*fb49*fb77 - fb16*fb53*fb77 - 30*fb16*fb65*fb72*fb74 - fb20 -
            fb22*m1 - fb23 + (3/2)*fb24*fb9*m3*mu - fb25*fb31*fb69 - 3*fb29 - fb30 - fb32*fb35 -
            fb38 + fb4*m1*r + fb4*m2*r + fb4*m3*r - fb46 + (3/2)*fb48*fb71*fb9*m2*mu - fb49*fb70
            + (3/2)*fb52*fb71*fb9*m1*mu - fb53*fb70 - fb58*fb72*fb73 - fb58*fb73*fb75 - fb60*m1 -
            fb60*m2 - fb64*fb75*fb76 - 2*fb68*fb7)
    B4 = (
            Q_nu + a*fb66*m2*r*sin_theta + 2*b*m1*nu_dot*r*sin_theta*theta_dot - delta_x*fb20 -
            delta_y*fb2 - delta_y*fb3 - fb2*r - fb3*r - fb39*fb67*fb79 + fb43 - fb44*fb66*fb79 - fb45
            - fb78*m1 - fb78*m2)
    mm0 = delta_y*m3
    mm1 = delta_x*m3
    mm2 = cos_theta**2
    mm3 = a**2*m2
    mm4 = sin_theta**2
    mm5 = b**2*m1
    mm6 = mm2*mm3 + mm2*mm5 + mm3*mm4 + mm4*mm5
    mm7 = a*m2
    mm8 = mm7*sin_theta
    mm9 = b*m1
    mm10 = mm9*sin_theta
    mm11 = cos_theta*r
    mm12 = mm11*mm9
    mm13 = r**2
    M0_0 = m3
    M0_1 = 0
    M0_2 = 0
    M0_3 = 0
    M0_4 = -m3*r - mm0
    M1_1 = m3
    M1_2 = 0
    M1_3 = m3
    M1_4 = mm1
    M2_2 = mm6
    M2_3 = -mm10 + mm8
    M2_4 = a*cos_theta*m2*r - mm12 - mm6
    M3_3 = m1 + m2 + m3
    M3_4 = mm1 + mm10 - mm8
    M4_4 = delta_x**2*m3 + delta_y**2*m3 + m1*mm13 + m2*mm13 + m3*mm13 + 2*mm0*r - 2*mm11*mm7 + 2*mm12 + mm6
    L1_0 = M0_1 / M0_0
    M1_1 -= L1_0 * M0_1
    M1_2 -= L1_0 * M0_2
    M1_3 -= L1_0 * M0_3
    M1_4 -= L1_0 * M0_4
    L2_0 = M0_2 / M0_0
    M2_2 -= L2_0 * M0_2
    M2_3 -= L2_0 * M0_3
    M2_4 -= L2_0 * M0_4
    L3_0 = M0_3 / M0_0
    M3_3 -= L3_0 * M0_3
    M3_4 -= L3_0 * M0_4
    L4_0 = M0_4 / M0_0
    M4_4 -= L4_0 * M0_4
    L2_1 = M1_2 / M1_1
    M2_2 -= L2_1 * M1_2
    M2_3 -= L2_1 * M1_3
    M2_4 -= L2_1 * M1_4
    L3_1 = M1_3 / M1_1
    M3_3 -= L3_1 * M1_3
    M3_4 -= L3_1 * M1_4
    L4_1 = M1_4 / M1_1
    M4_4 -= L4_1 * M1_4
    L3_2 = M2_3 / M2_2
    M3_3 -= L3_2 * M2_3
    M3_4 -= L3_2 * M2_4
    L4_2 = M2_4 / M2_2
    M4_4 -= L4_2 * M2_4
    L4_3 = M3_4 / M3_3
    M4_4 -= L4_3 * M3_4
    B1 -= L1_0 * B0
    B2 -= L2_0 * B0
    B3 -= L3_0 * B0
    B4 -= L4_0 * B0
    B2 -= L2_1 * B1
    B3 -= L3_1 * B1
    B4 -= L4_1 * B1
    B3 -= L3_2 * B2
    B4 -= L4_2 * B2
    B4 -= L4_3 * B3
    X4 = (B4) / M4_4
    X3 = (B3 - M3_4 * X4) / M3_3
    X2 = (B2 - M2_3 * X3 - M2_4 * X4) / M2_2
    X1 = (B1 - M1_2 * X2 - M1_3 * X3 - M1_4 * X4) / M1_1
    X0 = (B0 - M0_1 * X1 - M0_2 * X2 - M0_3 * X3 - M0_4 * X4) / M0_0
    dydt[0] = delta_x_dot
    dydt[1] = delta_y_dot
    dydt[2] = theta_dot
    dydt[3] = r_dot
    dydt[4] = nu_dot
    dydt[5] = X0
    dydt[6] = X1
    dydt[7] = X2
    dydt[8] = X3
    dydt[9] = X4


@njit(cache=True)
def family_forces(y, p, out):
    """out[f, k] = generalized force of family FAMILIES[f] on q_k (N, N, N m, N, N m)."""
    delta_x = y[0]
    delta_y = y[1]
    theta = y[2]
    r = y[3]
    delta_x_dot = y[5]
    delta_y_dot = y[6]
    theta_dot = y[7]
    r_dot = y[8]
    nu_dot = y[9]
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
    omega_earth = p[16]
    rho1 = p[17]
    rho2 = p[18]
    rho3 = p[19]
    sin_theta, cos_theta = sincos(theta)
    lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
    lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
    out[:, :] = 0.0
    # drag1: air drag on the tip-mass (3.32-3.34)
    f0_0 = b*sin_theta
    f0_1 = f0_0*nu_dot - f0_0*omega_earth - f0_0*theta_dot + r_dot
    f0_2 = b*cos_theta
    f0_3 = f0_2 + r
    f0_4 = f0_2*theta_dot - f0_3*nu_dot + f0_3*omega_earth
    f0_5 = math.sqrt(f0_1**2 + f0_4**2)
    f0_6 = (1/2)*A1*CD*f0_5*rho1
    f0_7 = f0_1*f0_6
    f0_8 = f0_0*f0_7
    out[0, 0] = 0
    out[0, 1] = 0
    out[0, 2] = -f0_2*f0_4*f0_6 + f0_8
    out[0, 3] = -f0_7
    out[0, 4] = (1/2)*A1*CD*f0_3*f0_4*f0_5*rho1 - f0_8
    # drag2: air drag on the main bus (3.32-3.34)
    f1_0 = a*sin_theta
    f1_1 = -f1_0*nu_dot + f1_0*omega_earth + f1_0*theta_dot + r_dot
    f1_2 = a*cos_theta
    f1_3 = -f1_2 + r
    f1_4 = -f1_2*theta_dot - f1_3*nu_dot + f1_3*omega_earth
    f1_5 = (1/2)*A2*CD*rho2*math.sqrt(f1_1**2 + f1_4**2)
    f1_6 = f1_1*f1_5
    f1_7 = f1_0*f1_6
    f1_8 = f1_4*f1_5
    out[1, 0] = 0
    out[1, 1] = 0
    out[1, 2] = f1_2*f1_8 - f1_7
    out[1, 3] = -f1_6
    out[1, 4] = f1_3*f1_8 + f1_7
    # drag3: air drag on the balloon (3.32-3.34)
    f2_0 = delta_y + r
    f2_1 = delta_x_dot - f2_0*nu_dot + f2_0*omega_earth
    f2_2 = delta_x*nu_dot - delta_x*omega_earth + delta_y_dot + r_dot
    f2_3 = math.sqrt(f2_1**2 + f2_2**2)
    f2_4 = (1/2)*A3*CD*f2_3*rho3
    f2_5 = f2_2*f2_4
    f2_6 = -f2_5
    out[2, 0] = -f2_1*f2_4
    out[2, 1] = f2_6
    out[2, 2] = 0
    out[2, 3] = f2_6
    out[2, 4] = (1/2)*A3*CD*f2_0*f2_1*f2_3*rho3 - delta_x*f2_5
    # spring1: tension of tether 1 (3.35-3.42)
    if lambda1 > l10:
        f3_0 = 1/l10
        f3_1 = E1*delta_x
        f3_2 = 1/lambda1
        f3_3 = E1*b
        f3_4 = E1*delta_y*f3_0
        out[3, 0] = E1*b*f3_0*sin_theta + E1*delta_x*f3_2 - f3_0*f3_1 - f3_2*f3_3*sin_theta
        out[3, 1] = E1*b*cos_theta*f3_0 + E1*delta_y*f3_2 - cos_theta*f3_2*f3_3 - f3_4
        out[3, 2] = (
                E1*b*cos_theta*delta_x*f3_0 + E1*b*delta_y*f3_2*sin_theta - b*cos_theta*f3_1*f3_2
                - b*f3_4*sin_theta)
        out[3, 3] = 0
        out[3, 4] = 0
    # spring2: tension of tether 2 (3.36-3.42)
    if lambda2 > l20:
        f4_0 = 1/lambda2
        f4_1 = E2*delta_x
        f4_2 = f4_0*f4_1
        f4_3 = 1/l20
        f4_4 = f4_1*f4_3
        f4_5 = E2*a
        f4_6 = f4_5*sin_theta
        f4_7 = E2*delta_y
        f4_8 = f4_0*f4_7
        f4_9 = f4_3*f4_7
        f4_10 = cos_theta*f4_5
        f4_11 = a*cos_theta
        f4_12 = a*sin_theta
        out[4, 0] = f4_0*f4_6 + f4_2 - f4_3*f4_6 - f4_4
        out[4, 1] = f4_0*f4_10 - f4_10*f4_3 + f4_8 - f4_9
        out[4, 2] = f4_11*f4_2 - f4_11*f4_4 - f4_12*f4_8 + f4_12*f4_9
        out[4, 3] = 0
        out[4, 4] = 0
    # damper1: damping of tether 1 along its stretch rate (variant (issue 5))
    if lambda1 > l10:
        f5_0 = 1/lambda1
        f5_1 = c1*f5_0
        f5_2 = b*cos_theta
        f5_3 = b*sin_theta
        f5_4 = (
                f5_0*max(E1 - E1*lambda1/l10, b*c1*delta_y*f5_0*sin_theta*theta_dot + c1*delta_x*
                delta_x_dot*f5_0 + c1*delta_y*delta_y_dot*f5_0 - delta_x*f5_1*f5_2*theta_dot -
                delta_x_dot*f5_1*f5_3 - delta_y_dot*f5_1*f5_2))
        f5_5 = delta_x*f5_4
        f5_6 = b*f5_4
        f5_7 = delta_y*f5_4
        out[5, 0] = -f5_5 + f5_6*sin_theta
        out[5, 1] = cos_theta*f5_6 - f5_7
        out[5, 2] = f5_2*f5_5 - f5_3*f5_7
        out[5, 3] = 0
        out[5, 4] = 0
    # damper2: damping of tether 2 along its stretch rate (variant (issue 5))
    if lambda2 > l20:
        f6_0 = 1/lambda2
        f6_1 = c2*f6_0
        f6_2 = delta_x_dot*f6_1
        f6_3 = delta_y_dot*f6_1
        f6_4 = a*cos_theta
        f6_5 = a*sin_theta
        f6_6 = f6_1*theta_dot
        f6_7 = (
                max(E2 - E2*lambda2/l20, delta_x*f6_2 + delta_x*f6_4*f6_6 + delta_y*f6_3 - delta_y*
                f6_5*f6_6 + f6_2*f6_5 + f6_3*f6_4))
        f6_8 = f6_0*f6_7
        f6_9 = delta_x*f6_8
        f6_10 = a*f6_8
        out[6, 0] = -f6_10*sin_theta - f6_9
        out[6, 1] = -cos_theta*f6_10 - delta_y*f6_8
        out[6, 2] = a*delta_y*f6_0*f6_7*sin_theta - f6_4*f6_9
        out[6, 3] = 0
        out[6, 4] = 0


@njit(cache=True)
def jacobi(y, p):
    """Total energy T + V (orbit and attitude) plus taut-tether spring energy [J].

    L = T − V has no explicit t, so this is the Jacobi integral: constant with drag
    and dampers off, otherwise dE/dt = Σ_k (Q_drag + Q_damper)_k q̇_k.
    """
    delta_x = y[0]
    delta_y = y[1]
    theta = y[2]
    r = y[3]
    delta_x_dot = y[5]
    delta_y_dot = y[6]
    theta_dot = y[7]
    r_dot = y[8]
    nu_dot = y[9]
    m1 = p[0]
    m2 = p[1]
    m3 = p[2]
    a = p[6]
    b = p[7]
    l10 = p[8]
    l20 = p[9]
    E1 = p[10]
    E2 = p[11]
    mu = p[15]
    J2 = p[20]
    R_E = p[21]
    sin_theta, cos_theta = sincos(theta)
    e0 = delta_y_dot*m3
    e1 = delta_x*nu_dot
    e2 = (1/2)*m3
    e3 = (1/2)*r_dot**2
    e4 = delta_y*m3
    e5 = delta_x_dot*nu_dot
    e6 = a*m2
    e7 = r_dot*sin_theta
    e8 = e7*theta_dot
    e9 = b*m1
    e10 = e9*nu_dot
    e11 = nu_dot**2
    e12 = e11*r
    e13 = e6*nu_dot
    e14 = cos_theta*r*theta_dot
    e15 = cos_theta*e12
    e16 = delta_x**2
    e17 = e11*e2
    e18 = delta_y**2
    e19 = r**2
    e20 = e11*e19
    e21 = (1/2)*m1
    e22 = (1/2)*m2
    e23 = cos_theta**2
    e24 = a**2
    e25 = e23*e24
    e26 = nu_dot*theta_dot
    e27 = e26*m2
    e28 = sin_theta**2
    e29 = e24*e28
    e30 = b**2
    e31 = e23*e30
    e32 = e26*m1
    e33 = e28*e30
    e34 = e11*e22
    e35 = theta_dot**2
    e36 = e22*e35
    e37 = e11*e21
    e38 = e21*e35
    e39 = 1/r
    e40 = 1/e19
    e41 = r**(-3)
    e42 = (1/2)*e41
    e43 = delta_y**3
    e44 = r**(-4)
    e45 = (3/2)*e44
    e46 = delta_y*e16
    e47 = 3*e44
    e48 = r**(-5)
    e49 = (3/2)*e48
    e50 = 6*e48
    e51 = r**(-6)
    e52 = 10*e51
    e53 = (15/2)*e51
    e54 = (1/2)*J2*R_E**2
    e55 = cos_theta*e40
    e56 = e23*e41
    e57 = cos_theta**3
    e58 = a**3
    e59 = e57*e58
    e60 = cos_theta*e28
    e61 = e58*e60
    e62 = cos_theta*e47
    e63 = b**3
    e64 = e57*e63
    h = (
            delta_x_dot**2*e2 + delta_y_dot**2*e2 + e0*e1 + e0*r_dot + e1*m3*r_dot - e10*e14 + e10*e7
            + e12*e4 + e13*e14 - e13*e7 - e15*e6 + e15*e9 + e16*e17 + e17*e18 + e2*e20 + e20*e21 +
            e20*e22 - e25*e27 + e25*e34 + e25*e36 - e27*e29 + e29*e34 + e29*e36 + e3*m1 + e3*m2 +
            e3*m3 - e31*e32 + e31*e37 + e31*e38 - e32*e33 + e33*e37 + e33*e38 - e4*e5 - e5*m3*r +
            e6*e8 - e8*e9 - m1*mu*(-b*e55 + e30*e56 - e33*e42 + e39 + e45*e60*e63 + e45*e64 + e54*
            (-b*e62 + (15/2)*cos_theta*e28*e51*e63 + 6*e23*e30*e48 - e33*e49 + e41 - e52*e64)) -
            m2*mu*(a*e55 + e24*e56 - e29*e42 + e39 - e45*e59 - e45*e61 + e54*(a*e62 + e23*e24*e50
            - e29*e49 + e41 + e52*e59 - e53*e61)) - m3*mu*(-delta_y*e40 - e16*e42 + e18*e41 + e39 +
            e43*e45 + e45*e46 + e54*(-delta_y*e47 - e16*e49 + e18*e50 + e41 - e43*e52 + e46*e53)))
    lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
    if lambda1 > l10:
        h += (1/2)*E1*(-l10 + lambda1)**2/l10
    lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
    if lambda2 > l20:
        h += (1/2)*E2*(-l20 + lambda2)**2/l20
    return h


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

    Positions (Eqs 3.10-3.12 about the orbit radius r).
    """
    delta_x = y[0]
    delta_y = y[1]
    theta = y[2]
    r = y[3]
    a = p[6]
    b = p[7]
    sin_theta, cos_theta = sincos(theta)
    return (
            math.hypot(b*sin_theta, b*cos_theta + r), math.hypot(-a*sin_theta, -a*cos_theta + r),
            math.hypot(delta_x, delta_y + r))
