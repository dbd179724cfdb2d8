"""GENERATED FILE - DO NOT EDIT.

Model 'exact-gravity': derived model with exact point-mass gravity mu/|r| (no binomial expansion, no truncation).
Produced by `make derive` (python -m derive) from derive/; regenerate instead
of editing.  sympy 1.14.0.  State, parameter and family orders are
listed in generated/layout.py.
"""
import math

from numba import njit

MODEL = 'exact-gravity'
FAMILIES = ('drag1', 'drag2', 'drag3', 'spring1', 'spring2', 'damper1', 'damper2')


@njit(cache=True)
def rhs(t, y, p, dydt):
    """State derivative dy/dt of model 'exact-gravity' (SI; layout in generated/layout.py)."""
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
    mu = p[16]
    omega = p[17]
    omega_earth = p[18]
    rho1 = p[19]
    rho2 = p[20]
    rho3 = p[21]
    sin_theta = math.sin(theta)
    cos_theta = math.cos(theta)
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
    Q_theta = (1/2)*A1*CD*b*d10*d6*rho1*sin_theta - A1*d10*d3*d7*d9*rho1 + (1/2)*A2*CD*a*cos_theta*d15*d16*rho2 - A2*d11*d12*d16*d3*rho2
    lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
    if lambda1 > l10:  # tether 1 taut: spring1, damper1
        t1_0 = b*cos_theta
        t1_1 = delta_x_dot - delta_y*omega + omega*t1_0 - t1_0*theta_dot
        t1_2 = b*sin_theta
        t1_3 = 1/lambda1
        t1_4 = -1 + lambda1/l10
        t1_5 = E1*t1_3*t1_4
        t1_6 = t1_5*(-delta_x + t1_2)
        t1_7 = c1*(delta_x*omega + delta_y_dot - omega*t1_2 + t1_2*theta_dot)
        t1_8 = -delta_y + t1_0
        Q_delta_x += -c1*t1_1 + t1_6
        Q_delta_y += t1_5*t1_8 - t1_7
        Q_theta += E1*b*sin_theta*t1_3*t1_4*t1_8 + b*c1*cos_theta*t1_1 - t1_0*t1_6 - t1_2*t1_7
    lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
    if lambda2 > l20:  # tether 2 taut: spring2, damper2
        t2_0 = a*cos_theta
        t2_1 = c2*(a*cos_theta*theta_dot + delta_x_dot - delta_y*omega - omega*t2_0)
        t2_2 = a*sin_theta
        t2_3 = E2*(-1 + lambda2/l20)/lambda2
        t2_4 = t2_3*(-delta_x - t2_2)
        t2_5 = c2*(delta_x*omega + delta_y_dot + omega*t2_2 - t2_2*theta_dot)
        t2_6 = t2_3*(-delta_y - t2_0)
        Q_delta_x += -t2_1 + t2_4
        Q_delta_y += -t2_5 + t2_6
        Q_theta += -t2_0*t2_1 + t2_0*t2_4 + t2_2*t2_5 - t2_2*t2_6
    # accelerations from M q'' + f(q, q') = Q (Lagrange, 3.26-3.30)
    dydt[0] = delta_x_dot
    dydt[1] = delta_y_dot
    dydt[2] = theta_dot
    a0 = 2*omega
    a1 = 1/m3
    a2 = omega**2
    a3 = 2/r0
    a4 = r0**(-2)
    a5 = a2*math.expm1(-1.5*math.log1p(a3*delta_y + a4*delta_x**2 + a4*delta_y**2))
    a6 = a**2
    a7 = b**2
    a8 = 1/(a6*m2 + a7*m1)
    a9 = a3*cos_theta
    a10 = a2*a8*r0*sin_theta
    dydt[3] = Q_delta_x*a1 + a0*delta_y_dot - a5*delta_x
    dydt[4] = Q_delta_y*a1 - a0*delta_x_dot - a5*delta_y - a5*r0
    dydt[5] = Q_theta*a8 - a*a10*m2*math.expm1(-1.5*math.log1p(-a*a9 + a4*a6)) + a10*b*m1*math.expm1(-1.5*math.log1p(a4*a7 + a9*b))


@njit(cache=True)
def family_forces(y, p, out):
    """out[f, k] = generalized force of family FAMILIES[f] on q_k (N, N, N m)."""
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
    mu = p[16]
    omega = p[17]
    omega_earth = p[18]
    rho1 = p[19]
    rho2 = p[20]
    rho3 = p[21]
    sin_theta = math.sin(theta)
    cos_theta = math.cos(theta)
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
    # damper1: damping of tether 1 (relative velocity) (3.43)
    if lambda1 > l10:
        f5_0 = b*cos_theta
        f5_1 = c1*(delta_x_dot - delta_y*omega + f5_0*omega - f5_0*theta_dot)
        f5_2 = b*sin_theta
        f5_3 = c1*(delta_x*omega + delta_y_dot - f5_2*omega + f5_2*theta_dot)
        out[5, 0] = -f5_1
        out[5, 1] = -f5_3
        out[5, 2] = f5_0*f5_1 - f5_2*f5_3
    # damper2: damping of tether 2 (relative velocity) (3.44)
    if lambda2 > l20:
        f6_0 = a*cos_theta
        f6_1 = c2*(a*cos_theta*theta_dot + delta_x_dot - delta_y*omega - f6_0*omega)
        f6_2 = a*sin_theta
        f6_3 = delta_x*omega + delta_y_dot + f6_2*omega - f6_2*theta_dot
        out[6, 0] = -f6_1
        out[6, 1] = -c2*f6_3
        out[6, 2] = a*c2*f6_3*sin_theta - f6_0*f6_1


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
    mu = p[16]
    omega = p[17]
    omega_earth = p[18]
    rho1 = p[19]
    rho2 = p[20]
    rho3 = p[21]
    sin_theta = math.sin(theta)
    cos_theta = math.cos(theta)
    e0 = omega**2
    e1 = e0*m3
    e2 = delta_x**2
    e3 = (1/2)*e0*m3
    e4 = delta_y**2
    e5 = cos_theta**2
    e6 = a**2
    e7 = (1/2)*e0
    e8 = e6*e7*m2
    e9 = theta_dot**2
    e10 = sin_theta**2
    e11 = b**2
    e12 = e11*e7*m1
    e13 = r0**2
    e14 = 2/r0
    e15 = 1/e13
    e16 = cos_theta*e14
    e17 = e11*e15
    e18 = e0*e13
    e19 = e15*e6
    h = a*cos_theta*e0*m2*r0 - b*cos_theta*e0*m1*r0 + (1/2)*delta_x_dot**2*m3 - delta_y*e1*r0 + (1/2)*delta_y_dot**2*m3 - e1*e13*math.expm1(-0.5*math.log1p(delta_y*e14 + e15*e2 + e15*e4)) + (1/2)*e10*e11*e9*m1 - e10*e12 + (1/2)*e10*e6*e9*m2 - e10*e8 + (1/2)*e11*e5*e9*m1 - e12*e5 - e18*m1*math.expm1(-0.5*math.log1p(b*e16 + e10*e17 + e17*e5)) - e18*m2*math.expm1(-0.5*math.log1p(-a*e16 + e10*e19 + e19*e5)) - e2*e3 - e3*e4 + (1/2)*e5*e6*e9*m2 - e5*e8
    lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
    if lambda1 > l10:
        h += (1/2)*E1*(-l10 + lambda1)**2/l10
    lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
    if lambda2 > l20:
        h += (1/2)*E2*(-l20 + lambda2)**2/l20
    return h
