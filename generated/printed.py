"""GENERATED FILE - DO NOT EDIT.

Model 'printed': Eqs 3.48-3.50 exactly as printed in the thesis, errata included.
Produced by `make derive` (python -m derive) from derive/; regenerate instead
of editing.  sympy 1.14.0.  State, parameter and family orders are
listed in generated/layout.py.
"""
import math

from numba import njit

MODEL = 'printed'
FAMILIES = ('drag1', 'drag2', 'drag3', 'spring1', 'spring2', 'damper1', 'damper2')


@njit(cache=True)
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
    mu = p[16]
    omega = p[17]
    omega_earth = p[18]
    rho1 = p[19]
    rho2 = p[20]
    rho3 = p[21]
    sin_theta = math.sin(theta)
    cos_theta = math.cos(theta)
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
        Q_theta += -c2*t2_1*(delta_x_dot + omega*t2_8 - t2_0 - t2_8*theta_dot) + c2*t2_2*(-omega*t2_7 + t2_5 + t2_7*theta_dot) + t2_4*(t2_1*t2_3 - t2_2*t2_6)
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
    a11 = a10*a4
    a12 = a11*r0*math.sin(2*theta)
    dydt[3] = Q_delta_x*a1 + a0*delta_y_dot + a2*a5*delta_x
    dydt[4] = Q_delta_y*a1 - a0*delta_x_dot + a5 + (3/2)*a6*delta_x**2 + (9/2)*a6*delta_y**2
    dydt[5] = 2*Q_theta*a10*r0 + 3*a**3*a10*a3*m2*sin_theta - a11*b**3*m1*sin_theta - a12*a8 - a12*a9


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
        out[6, 2] = a*c2*sin_theta*(f6_3 - f6_5*omega + f6_5*theta_dot) - c2*f6_1*(delta_x_dot - f6_0 + f6_4*omega - f6_4*theta_dot)


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
    h = (3/2)*cos_theta*e1*e13*e16*e7*m2 - cos_theta*e22*e23*e7 - delta_x**4*e12 + (1/2)*delta_x_dot**2*m3 - delta_y**4*e12 - delta_y**3*e14 - delta_y*e14*e15 + (1/2)*delta_y_dot**2*m3 - 3/4*e0*e11*e15 - e0*e3 + (3/2)*e1*e13*e16*e17*m2 - e17*e22*e23 - e19*e20 - e19*e25 - e2*e4*e5*m2 - e2*e8*e9 - e20*e21 - e20*e26*e4 - e21*e25 - e24*e26*e9 + (1/2)*e4*e5*e6*m2 + (1/2)*e4*e6*e8*m1 + (1/2)*e5*e6*e7*m2 + (1/2)*e6*e7*e8*m1
    lambda1 = math.sqrt((b*cos_theta - delta_y)**2 + (b*sin_theta - delta_x)**2)
    if lambda1 > l10:
        h += (1/2)*E1*(-l10 + lambda1)**2/l10
    lambda2 = math.sqrt((-a*cos_theta - delta_y)**2 + (-a*sin_theta - delta_x)**2)
    if lambda2 > l20:
        h += (1/2)*E2*(-l20 + lambda2)**2/l20
    return h
