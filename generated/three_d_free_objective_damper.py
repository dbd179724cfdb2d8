"""GENERATED FILE - DO NOT EDIT.

Model '3d-free-objective-damper': 3-D model on a free orbit (r, nu as coordinates), truncated binomial
gravity, J2 at each body's latitude, Kelvin-Voigt tether dampers.
Produced by `make derive` (python -m derive) from derive/three_d/free3d.py and
derive/orbit_codegen.py; regenerate instead of editing.  docs/three-d.md, docs/orbit.md.  sympy 1.14.0.
Reduces to the model '3d-objective-damper' on a circular orbit.

State vector y (index, name, unit):
   0  delta_x      m
   1  delta_y      m
   2  delta_z      m
   3  phi          rad
   4  theta        rad
   5  psi          rad
   6  r            m
   7  nu           rad
   8  delta_x_dot  m/s
   9  delta_y_dot  m/s
  10  delta_z_dot  m/s
  11  phi_dot      rad/s
  12  theta_dot    rad/s
  13  psi_dot      rad/s
  14  r_dot        m/s
  15  nu_dot       rad/s

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
  22  I1_roll      kg m^2    tip-mass principal inertia about its own roll axis
  23  I1_pitch     kg m^2    tip-mass principal inertia about its own pitch axis
  24  I1_yaw       kg m^2    tip-mass principal inertia about its own yaw axis
  25  I2_roll      kg m^2    main bus principal inertia about its own roll axis
  26  I2_pitch     kg m^2    main bus principal inertia about its own pitch axis
  27  I2_yaw       kg m^2    main bus principal inertia about its own yaw axis
"""
import math

from numba import njit

from .trig import sincos

MODEL = '3d-free-objective-damper'
DESCRIPTION = (
    "3-D model on a free orbit (r, nu as coordinates), truncated binomial gravity, J2 at each body's "
    'latitude, Kelvin-Voigt tether dampers'
)
GEOMETRY = "3d"  # roll, pitch, yaw and an out-of-plane balloon
ORBIT = "free"  # r and ν are coordinates: gravity, J2 and drag move the orbit
CIRCULAR_TWIN = '3d-objective-damper'  # the model this one reduces to on a circular orbit
FAMILIES = ('drag1', 'drag2', 'drag3', 'spring1', 'spring2', 'damper1', 'damper2')
STATE = (
    'delta_x', 'delta_y', 'delta_z', 'phi', 'theta', 'psi', 'r', 'nu', 'delta_x_dot', 'delta_y_dot',
    'delta_z_dot', 'phi_dot', 'theta_dot', 'psi_dot', 'r_dot', 'nu_dot',
)
STATE_UNITS = (
    'm', 'm', 'm', 'rad', 'rad', 'rad', 'm', 'rad', 'm/s', 'm/s', 'm/s', 'rad/s', 'rad/s', 'rad/s', 'm/s',
    'rad/s',
)
PARAMETERS = (
    'm1', 'm2', 'm3', 'A1', 'A2', 'A3', 'a', 'b', 'l10', 'l20', 'E1', 'E2', 'c1', 'c2', 'CD', 'mu',
    'omega_earth', 'rho1', 'rho2', 'rho3', 'J2', 'R_E', 'I1_roll', 'I1_pitch', 'I1_yaw', 'I2_roll',
    'I2_pitch', 'I2_yaw',
)
PARAMETER_UNITS = (
    'kg', 'kg', 'kg', 'm^2', 'm^2', 'm^2', 'm', 'm', 'm', 'm', 'N', 'N', 'N s/m', 'N s/m', '1', 'm^3/s^2',
    'rad/s', 'kg/m^3', 'kg/m^3', 'kg/m^3', '1', 'm', 'kg m^2', 'kg m^2', 'kg m^2', 'kg m^2', 'kg m^2',
    'kg m^2',
)

Y_DELTA_X = 0
Y_DELTA_Y = 1
Y_DELTA_Z = 2
Y_PHI = 3
Y_THETA = 4
Y_PSI = 5
Y_R = 6
Y_NU = 7
Y_DELTA_X_DOT = 8
Y_DELTA_Y_DOT = 9
Y_DELTA_Z_DOT = 10
Y_PHI_DOT = 11
Y_THETA_DOT = 12
Y_PSI_DOT = 13
Y_R_DOT = 14
Y_NU_DOT = 15

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
P_I1_ROLL = 22
P_I1_PITCH = 23
P_I1_YAW = 24
P_I2_ROLL = 25
P_I2_PITCH = 26
P_I2_YAW = 27


@njit(cache=True)
def rhs(t, y, p, dydt):
    """State derivative dy/dt of model '3d-free-objective-damper' (SI; y, p as in STATE, PARAMETERS)."""
    delta_x = y[0]
    delta_y = y[1]
    delta_z = y[2]
    phi = y[3]
    theta = y[4]
    psi = y[5]
    r = y[6]
    delta_x_dot = y[8]
    delta_y_dot = y[9]
    delta_z_dot = y[10]
    phi_dot = y[11]
    theta_dot = y[12]
    psi_dot = y[13]
    r_dot = y[14]
    nu_dot = y[15]
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
    I1_roll = p[22]
    I1_pitch = p[23]
    I1_yaw = p[24]
    I2_roll = p[25]
    I2_pitch = p[26]
    I2_yaw = p[27]
    sin_phi, cos_phi = sincos(phi)
    sin_theta, cos_theta = sincos(theta)
    sin_psi, cos_psi = sincos(psi)
    # air drag on the three bodies (3.32-3.34, co-rotating air)
    d0 = delta_y + r
    d1 = -d0*nu_dot + d0*omega_earth + delta_x_dot
    d2 = delta_x*nu_dot - delta_x*omega_earth + delta_y_dot + r_dot
    d3 = (1/2)*CD
    d4 = A3*d3*rho3*math.sqrt(d1**2 + d2**2 + delta_z_dot**2)
    d5 = d1*d4
    d6 = d2*d4
    d7 = b**2
    d8 = cos_phi**2
    d9 = d8*phi_dot**2
    d10 = b*sin_theta
    d11 = cos_phi*d10
    d12 = phi_dot*sin_phi
    d13 = cos_theta*d12
    d14 = b*cos_phi*nu_dot*sin_theta - b*d13 - d11*omega_earth - d11*theta_dot + r_dot
    d15 = cos_phi*cos_theta
    d16 = b*d15
    d17 = d16 + r
    d18 = -d10*d12 + d16*theta_dot - d17*nu_dot + d17*omega_earth
    d19 = math.sqrt(d14**2 + d18**2 + d7*d9)
    d20 = A1*d19*d3*rho1
    d21 = d8*phi_dot
    d22 = a**2
    d23 = a*sin_theta
    d24 = cos_phi*d23
    d25 = a*d13 - d24*nu_dot + d24*omega_earth + d24*theta_dot + r_dot
    d26 = a*d15
    d27 = -d26 + r
    d28 = a*phi_dot*sin_phi*sin_theta - d26*theta_dot - d27*nu_dot + d27*omega_earth
    d29 = math.sqrt(d22*d9 + d25**2 + d28**2)
    d30 = A2*d29*d3*rho2
    d31 = d25*d30
    d32 = d28*d30
    d33 = d18*d20
    d34 = d14*d20
    d35 = -d11*d34 + d24*d31
    Q_delta_x = -d5
    Q_delta_y = -d6
    Q_delta_z = -d4*delta_z_dot
    Q_phi = (
            (1/2)*A1*CD*b*cos_theta*d14*d19*rho1*sin_phi + (1/2)*A1*CD*b*d18*d19*rho1*sin_phi*
            sin_theta - a*cos_theta*d31*sin_phi - d20*d21*d7 - d21*d22*d30 - d23*d32*sin_phi)
    Q_theta = (1/2)*A2*CD*a*cos_phi*cos_theta*d28*d29*rho2 - d16*d33 - d35
    Q_psi = 0
    Q_r = -d31 - d34 - d6
    Q_nu = d0*d5 + d17*d33 + d27*d32 + d35 - d6*delta_x
    lambda1 = (
            math.sqrt((b*sin_phi - delta_z)**2 + (b*cos_phi*cos_theta - delta_y)**2 + (b*cos_phi*
            sin_theta - delta_x)**2))
    if lambda1 > l10:  # tether 1 taut: spring1, damper1
        t1_0 = 1/l10
        t1_1 = E1*delta_x
        t1_2 = t1_0*t1_1
        t1_3 = 1/lambda1
        t1_4 = E1*t1_3
        t1_5 = b*cos_phi
        t1_6 = sin_theta*t1_5
        t1_7 = E1*t1_0
        t1_8 = c1*t1_3
        t1_9 = b*sin_phi
        t1_10 = cos_theta*t1_5
        t1_11 = phi_dot*t1_8
        t1_12 = b**2
        t1_13 = cos_theta**2
        t1_14 = cos_phi*sin_phi*t1_12
        t1_15 = t1_11*t1_14
        t1_16 = sin_theta**2
        t1_17 = (
                max(E1 - lambda1*t1_7, b*c1*cos_phi*delta_y*sin_theta*t1_3*theta_dot + b*c1*
                cos_theta*delta_y*phi_dot*sin_phi*t1_3 + b*c1*delta_x*phi_dot*sin_phi*sin_theta*
                t1_3 + c1*cos_phi*phi_dot*sin_phi*t1_12*t1_3 + c1*delta_x*delta_x_dot*t1_3 + c1*
                delta_y*delta_y_dot*t1_3 + c1*delta_z*delta_z_dot*t1_3 - delta_x*t1_10*t1_8*theta_dot
                - delta_x_dot*t1_6*t1_8 - delta_y_dot*t1_10*t1_8 - delta_z*t1_11*t1_5 - delta_z_dot*
                t1_8*t1_9 - t1_13*t1_15 - t1_15*t1_16))
        t1_18 = t1_17*t1_3
        t1_19 = delta_x*t1_18
        t1_20 = delta_y*t1_7
        t1_21 = delta_y*t1_18
        t1_22 = cos_theta*t1_9
        t1_23 = sin_theta*t1_9
        t1_24 = t1_14*t1_4
        Q_delta_x += (
                E1*b*cos_phi*sin_theta*t1_0 + E1*delta_x*t1_3 + b*cos_phi*sin_theta*t1_17*t1_3 -
                t1_19 - t1_2 - t1_4*t1_6)
        Q_delta_y += (
                E1*b*cos_phi*cos_theta*t1_0 + E1*delta_y*t1_3 + b*cos_phi*cos_theta*t1_17*t1_3 -
                t1_10*t1_4 - t1_20 - t1_21)
        Q_delta_z += (
                E1*b*sin_phi*t1_0 + E1*delta_z*t1_3 + b*sin_phi*t1_17*t1_3 - delta_z*t1_18 -
                delta_z*t1_7 - t1_4*t1_9)
        Q_phi += (
                E1*b*cos_phi*delta_z*t1_0 + E1*b*cos_theta*delta_y*sin_phi*t1_3 + E1*b*delta_x*
                sin_phi*sin_theta*t1_3 + E1*cos_phi*sin_phi*t1_0*t1_12*t1_13 + E1*cos_phi*sin_phi*
                t1_0*t1_12*t1_16 + E1*cos_phi*sin_phi*t1_12*t1_3 + b*cos_phi*delta_z*t1_17*t1_3 +
                cos_phi*sin_phi*t1_12*t1_13*t1_17*t1_3 + cos_phi*sin_phi*t1_12*t1_16*t1_17*t1_3 -
                delta_z*t1_4*t1_5 - t1_13*t1_24 - t1_14*t1_18 - t1_14*t1_7 - t1_16*t1_24 - t1_19*t1_23
                - t1_2*t1_23 - t1_20*t1_22 - t1_21*t1_22)
        Q_theta += (
                E1*b*cos_phi*cos_theta*delta_x*t1_0 + E1*b*cos_phi*delta_y*sin_theta*t1_3 + b*
                cos_phi*cos_theta*delta_x*t1_17*t1_3 - t1_1*t1_10*t1_3 - t1_20*t1_6 - t1_21*t1_6)
        Q_psi += 0
        Q_r += 0
        Q_nu += 0
    lambda2 = (
            math.sqrt((-a*sin_phi - delta_z)**2 + (-a*cos_phi*cos_theta - delta_y)**2 + (-a*cos_phi*
            sin_theta - delta_x)**2))
    if lambda2 > l20:  # tether 2 taut: spring2, damper2
        t2_0 = 1/l20
        t2_1 = E2*delta_x
        t2_2 = t2_0*t2_1
        t2_3 = 1/lambda2
        t2_4 = E2*t2_0
        t2_5 = a*cos_phi
        t2_6 = sin_theta*t2_5
        t2_7 = c2*t2_3
        t2_8 = delta_x_dot*t2_7
        t2_9 = delta_y_dot*t2_7
        t2_10 = delta_z_dot*t2_7
        t2_11 = a*sin_phi
        t2_12 = cos_theta*t2_5
        t2_13 = phi_dot*t2_7
        t2_14 = t2_7*theta_dot
        t2_15 = a**2*cos_phi*sin_phi
        t2_16 = t2_13*t2_15
        t2_17 = cos_theta*t2_11
        t2_18 = sin_theta*t2_11
        t2_19 = cos_theta**2
        t2_20 = sin_theta**2
        t2_21 = (
                t2_3*max(E2 - lambda2*t2_4, delta_x*t2_12*t2_14 - delta_x*t2_13*t2_18 + delta_x*t2_8 -
                delta_y*t2_13*t2_17 - delta_y*t2_14*t2_6 + delta_y*t2_9 + delta_z*t2_10 + delta_z*
                t2_13*t2_5 + t2_10*t2_11 + t2_12*t2_9 - t2_16*t2_19 - t2_16*t2_20 + t2_16 + t2_6*t2_8))
        t2_22 = delta_x*t2_21
        t2_23 = delta_y*t2_4
        t2_24 = delta_y*t2_21
        t2_25 = delta_z*t2_4
        t2_26 = delta_z*t2_21
        t2_27 = E2*t2_3
        t2_28 = t2_15*t2_27
        t2_29 = delta_y*t2_27
        t2_30 = t2_1*t2_3
        t2_31 = t2_15*t2_4
        t2_32 = t2_15*t2_21
        Q_delta_x += E2*a*cos_phi*sin_theta*t2_3 + E2*delta_x*t2_3 - t2_2 - t2_21*t2_6 - t2_22 - t2_4*t2_6
        Q_delta_y += E2*a*cos_phi*cos_theta*t2_3 + E2*delta_y*t2_3 - t2_12*t2_21 - t2_12*t2_4 - t2_23 - t2_24
        Q_delta_z += E2*a*sin_phi*t2_3 + E2*delta_z*t2_3 - t2_11*t2_21 - t2_11*t2_4 - t2_25 - t2_26
        Q_phi += (
                delta_z*t2_27*t2_5 + t2_17*t2_23 + t2_17*t2_24 - t2_17*t2_29 + t2_18*t2_2 + t2_18*
                t2_22 - t2_18*t2_30 - t2_19*t2_28 + t2_19*t2_31 + t2_19*t2_32 - t2_20*t2_28 + t2_20*
                t2_31 + t2_20*t2_32 - t2_25*t2_5 - t2_26*t2_5 + t2_28 - t2_31 - t2_32)
        Q_theta += -t2_12*t2_2 - t2_12*t2_22 + t2_12*t2_30 + t2_23*t2_6 + t2_24*t2_6 - t2_29*t2_6
        Q_psi += 0
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
    fb8 = fb7*m3
    fb9 = delta_x*delta_y
    fb10 = r**(-4)
    fb11 = fb10*mu
    fb12 = fb11*m3
    fb13 = 3*fb12
    fb14 = r**(-5)
    fb15 = m3*mu
    fb16 = fb14*fb15
    fb17 = R_E**2
    fb18 = J2*fb17
    fb19 = fb16*fb18
    fb20 = r**(-6)
    fb21 = fb15*fb18
    fb22 = fb20*fb21
    fb23 = delta_y**2
    fb24 = fb12*fb23
    fb25 = r**(-2)
    fb26 = fb25*mu
    fb27 = delta_x_dot*fb1
    fb28 = delta_x**2
    fb29 = (3/2)*fb11
    fb30 = fb29*m3
    fb31 = delta_z**2
    fb32 = 6*fb16
    fb33 = delta_y*fb32
    fb34 = (
            delta_y*fb0*fb7 + delta_y*fb5 - fb18*fb30 + fb18*fb33 - 15*fb22*fb23 + (15/4)*fb22*fb28
            + (45/4)*fb22*fb31 - fb26*m3 - fb27 + fb28*fb30 + fb30*fb31 + fb5*r)
    fb35 = delta_y*delta_z
    fb36 = I1_yaw*cos_phi
    fb37 = psi_dot*theta_dot
    fb38 = I2_yaw*cos_phi
    fb39 = cos_psi*sin_psi
    fb40 = I1_pitch*fb39
    fb41 = phi_dot*psi_dot
    fb42 = 2*fb41
    fb43 = fb36*sin_phi
    fb44 = 2*nu_dot
    fb45 = fb44*theta_dot
    fb46 = fb38*sin_phi
    fb47 = theta_dot**2
    fb48 = I1_pitch*cos_phi
    fb49 = cos_psi**2
    fb50 = nu_dot*psi_dot
    fb51 = fb49*fb50
    fb52 = sin_psi**2
    fb53 = fb37*fb52
    fb54 = fb37*fb49
    fb55 = I1_roll*cos_phi
    fb56 = fb50*fb52
    fb57 = I2_pitch*cos_phi
    fb58 = I2_roll*cos_phi
    fb59 = fb44*r_dot
    fb60 = sin_phi*sin_theta
    fb61 = b*fb60
    fb62 = fb61*m1
    fb63 = cos_theta*sin_phi
    fb64 = fb26*m2
    fb65 = a*fb64
    fb66 = fb4*r
    fb67 = fb66*m1
    fb68 = b*fb63
    fb69 = fb4*sin_phi
    fb70 = fb48*fb49
    fb71 = fb47*sin_phi
    fb72 = fb52*fb55
    fb73 = fb49*fb57
    fb74 = fb52*fb58
    fb75 = I2_pitch*fb29
    fb76 = a*fb63
    fb77 = I2_roll*fb29
    fb78 = I2_yaw*fb29
    fb79 = a**2
    fb80 = phi_dot**2
    fb81 = b**2
    fb82 = cos_phi*m2
    fb83 = fb79*fb82
    fb84 = fb7*sin_phi
    fb85 = fb83*fb84
    fb86 = cos_phi*m1
    fb87 = fb81*fb86
    fb88 = fb84*fb87
    fb89 = sin_phi**3
    fb90 = cos_theta**2
    fb91 = I2_yaw*a
    fb92 = cos_theta*fb89
    fb93 = 3*fb11
    fb94 = fb92*fb93
    fb95 = 3*fb7
    fb96 = fb95*sin_theta
    fb97 = cos_theta*fb96
    fb98 = fb39*fb97
    fb99 = fb83*fb90
    fb100 = fb80*sin_phi
    fb101 = fb100*fb83
    fb102 = sin_theta**2
    fb103 = fb102*fb83
    fb104 = fb87*fb90
    fb105 = fb100*fb87
    fb106 = fb102*fb87
    fb107 = cos_phi**2
    fb108 = I1_yaw*fb107
    fb109 = 6*fb11
    fb110 = fb109*fb68
    fb111 = a**3
    fb112 = b**3
    fb113 = fb112*m1
    fb114 = fb93*sin_theta
    fb115 = b*fb114
    fb116 = sin_phi**2
    fb117 = fb116*fb40
    fb118 = fb107*fb39
    fb119 = I1_roll*fb118
    fb120 = I2_pitch*fb118
    fb121 = a*fb114
    fb122 = I2_roll*fb39
    fb123 = fb116*fb122
    fb124 = fb18*fb29
    fb125 = fb124*m2
    fb126 = I1_pitch*fb49
    fb127 = b*fb94
    fb128 = 3*fb84
    fb129 = fb70*fb90
    fb130 = I1_roll*fb52
    fb131 = fb128*fb90
    fb132 = cos_theta**3
    fb133 = b*fb132
    fb134 = 2*fb90
    fb135 = fb111*m2
    fb136 = fb107*fb135
    fb137 = I1_pitch*fb118
    fb138 = sin_theta**3
    fb139 = b*fb138
    fb140 = fb139*fb93
    fb141 = I1_pitch*fb52
    fb142 = (15/2)*fb11
    fb143 = fb102*fb68
    fb144 = fb142*fb143
    fb145 = I1_roll*fb39
    fb146 = I2_pitch*fb49
    fb147 = fb107*fb146
    fb148 = fb109*fb76
    fb149 = I2_pitch*fb39
    fb150 = fb138*fb93
    fb151 = a*fb150
    fb152 = I2_roll*fb118
    fb153 = I2_roll*fb52
    fb154 = fb107*fb153
    fb155 = I2_yaw*fb107
    fb156 = 9*fb11
    fb157 = fb14*mu
    fb158 = fb157*fb18
    fb159 = fb158*sin_phi
    fb160 = (9/2)*fb159
    fb161 = (9/2)*fb11
    fb162 = fb161*fb89
    fb163 = fb107*fb113
    fb164 = fb132*sin_phi
    fb165 = fb11*sin_theta
    fb166 = fb165*fb90
    fb167 = 12*fb166
    fb168 = b*fb167
    fb169 = a*fb167
    fb170 = a*fb156*fb164
    fb171 = a*fb94
    fb172 = fb18*mu
    fb173 = fb172*fb20
    fb174 = (45/4)*fb173
    fb175 = fb102*fb161
    fb176 = fb107*fb110
    fb177 = 6*fb159
    fb178 = (45/2)*fb173
    fb179 = 15*fb173
    fb180 = fb66*m2
    fb181 = cos_phi*sin_theta
    fb182 = fb26*m1
    fb183 = b*fb181
    fb184 = fb49*fb97
    fb185 = I2_pitch*fb52
    fb186 = cos_phi**3
    fb187 = fb138*fb186
    fb188 = fb187*fb93
    fb189 = I1_yaw*b
    fb190 = a*fb181
    fb191 = fb29*sin_theta
    fb192 = a*fb38
    fb193 = fb187*fb29
    fb194 = I1_pitch*fb29
    fb195 = I1_roll*fb29
    fb196 = b*fb36
    fb197 = fb102*fb128
    fb198 = fb116*fb192
    fb199 = fb81*m1
    fb200 = fb107*fb199
    fb201 = fb79*m2
    fb202 = fb107*fb201
    fb203 = fb116*fb184
    fb204 = fb116*fb97
    fb205 = fb116*fb196
    fb206 = fb186*fb189
    fb207 = (39/2)*fb166
    fb208 = fb48*fb52
    fb209 = fb139*fb142
    fb210 = fb49*fb55
    fb211 = fb116*fb29
    fb212 = fb211*sin_theta
    fb213 = fb112*fb86
    fb214 = fb113*fb186
    fb215 = fb191*fb90
    fb216 = fb111*fb82
    fb217 = fb135*fb186
    fb218 = fb138*fb142
    fb219 = a*fb57
    fb220 = fb219*fb52
    fb221 = a*fb58
    fb222 = fb221*fb49
    fb223 = fb186*fb91
    fb224 = 15*fb166
    fb225 = fb115*fb116
    fb226 = fb116*fb151
    fb227 = fb116*fb140
    fb228 = fb116*fb121
    fb229 = b*fb224
    fb230 = (15/4)*fb173
    fb231 = fb187*fb230
    fb232 = a*fb82
    fb233 = fb124*sin_theta
    fb234 = b*fb86
    fb235 = fb39*fb55
    fb236 = fb133*fb235
    fb237 = 12*fb11
    fb238 = fb237*sin_phi
    fb239 = fb219*fb39
    fb240 = fb164*fb237
    fb241 = fb68*fb93
    fb242 = fb39*fb57
    fb243 = fb76*fb93
    fb244 = fb39*fb48
    fb245 = fb39*fb58
    fb246 = fb133*fb244
    fb247 = fb221*fb39
    fb248 = fb178*fb90*sin_theta
    fb249 = fb116*fb174
    fb250 = fb249*sin_theta
    fb251 = b*fb116
    fb252 = fb251*fb72
    fb253 = cos_theta*fb157
    fb254 = (15/2)*fb18*fb253*sin_theta
    fb255 = a*fb116
    fb256 = fb207*fb255
    fb257 = 33*fb11
    fb258 = fb143*fb257
    fb259 = fb102*fb257*fb76
    fb260 = fb39*fb80
    fb261 = I1_roll*fb260
    fb262 = I2_roll*fb260
    fb263 = fb41*fb52
    fb264 = I1_pitch*fb260
    fb265 = fb41*fb49
    fb266 = I2_pitch*fb260
    fb267 = phi_dot*theta_dot
    fb268 = 2*fb267
    fb269 = nu_dot*phi_dot
    fb270 = 2*fb269
    fb271 = fb269*fb70
    fb272 = 2*sin_phi
    fb273 = 2*fb50
    fb274 = fb269*fb72
    fb275 = 2*fb37
    fb276 = fb269*fb73
    fb277 = fb269*fb74
    fb278 = cos_theta*fb232
    fb279 = fb267*fb70
    fb280 = fb267*fb72
    fb281 = fb267*fb73
    fb282 = fb267*fb74
    fb283 = cos_theta*fb234
    fb284 = fb270*sin_phi
    fb285 = fb268*sin_phi
    fb286 = (
            -fb103*fb284 + fb103*fb285 - fb104*fb284 + fb104*fb285 - fb106*fb284 + fb106*fb285 + fb119*
            fb273 - fb119*fb275 - fb120*fb273 + fb120*fb275 - fb137*fb273 + fb137*fb275 + fb152*fb273 -
            fb152*fb275 + fb261*sin_phi + fb262*sin_phi - fb263*fb48 - fb263*fb57 - fb264*sin_phi -
            fb265*fb55 - fb265*fb58 - fb266*sin_phi - fb268*fb43 - fb268*fb46 + fb270*fb43 + fb270*
            fb46 - fb271*fb272 - fb272*fb274 - fb272*fb276 - fb272*fb277 + fb272*fb279 + fb272*fb280 +
            fb272*fb281 + fb272*fb282 - fb278*fb59 + fb283*fb59 - fb284*fb99 + fb285*fb99 + fb36*fb41
            + fb38*fb41 + fb41*fb70 + fb41*fb72 + fb41*fb73 + fb41*fb74)
    fb287 = fb267*fb52
    fb288 = fb267*fb49
    fb289 = fb269*fb52
    fb290 = fb269*fb49
    fb291 = fb102*fb95
    fb292 = fb291*fb39
    fb293 = fb63*fb96
    fb294 = fb293*fb49
    fb295 = fb61*fb93
    fb296 = a*fb60
    fb297 = fb296*fb93
    fb298 = fb52*fb57
    fb299 = fb49*fb58
    fb300 = fb116*fb90*fb95
    fb301 = cos_theta*fb109
    fb302 = fb244*fb301
    fb303 = b*fb102
    fb304 = 15*fb11
    fb305 = cos_theta*fb235
    fb306 = fb303*fb305
    fb307 = cos_theta*fb239
    fb308 = fb109*fb116
    fb309 = fb307*fb308
    fb310 = fb102*fb304
    fb311 = fb116*fb247*fb301
    fb312 = fb140*sin_phi
    fb313 = fb151*sin_phi
    fb314 = fb150*sin_phi
    fb315 = fb116*fb156
    fb316 = fb237*fb90
    fb317 = fb316*fb61
    fb318 = fb132*fb315
    fb319 = fb296*fb316
    fb320 = delta_y**3
    fb321 = cos_theta*fb4
    fb322 = fb175*fb49
    fb323 = fb161*fb90
    fb324 = fb132*fb157
    fb325 = 18*fb324
    fb326 = 6*fb253
    fb327 = 6*fb324
    fb328 = fb90*fb93
    fb329 = 2*fb7
    fb330 = fb296*m2
    fb331 = b*fb326
    fb332 = r**(-7)
    fb333 = fb21*fb332
    fb334 = fb102*fb29
    fb335 = fb116*fb323
    fb336 = fb335*fb52
    fb337 = 12*fb253
    fb338 = fb102*fb337
    fb339 = fb116*fb326
    fb340 = fb102*fb326
    fb341 = delta_y*fb333
    fb342 = 30*fb253
    fb343 = fb303*fb342
    fb344 = fb172*fb332
    fb345 = fb217*fb344
    fb346 = 30*fb132
    fb347 = fb251*fb325
    fb348 = fb179*fb90
    fb349 = fb251*fb337
    fb350 = 9*fb165*fb63
    fb351 = 6*fb158
    fb352 = fb255*fb337
    fb353 = fb255*fb325
    fb354 = fb102*fb342
    fb355 = fb214*fb344
    fb356 = fb102*fb230
    fb357 = 12*fb157
    fb358 = fb244*fb357
    fb359 = fb357*sin_phi
    fb360 = fb138*fb359
    fb361 = fb255*fb338
    fb362 = fb296*fb357
    fb363 = fb235*fb61
    fb364 = (135/2)*cos_theta*fb116*fb344
    fb365 = (45/2)*cos_theta*fb102
    fb366 = 48*fb157*fb90
    fb367 = fb296*fb366
    fb368 = m1*r
    fb369 = r*sin_theta
    fb370 = fb234*fb369
    B0 = Q_delta_x - 3/2*delta_x*fb19 + delta_x*fb5 - delta_x*fb8 + fb13*fb9 + fb2 + (15/2)*fb22*fb9 + fb3
    B1 = Q_delta_y + (9/2)*fb24 + fb34
    B2 = Q_delta_z - 9/2*delta_z*fb19 - delta_z*fb8 + fb13*fb35 + (45/2)*fb22*fb35
    B3 = (
            12*I1_pitch*b*cos_psi*fb10*fb107*fb90*mu*sin_psi*sin_theta + 3*I1_pitch*b*cos_psi*
            fb10*fb107*mu*sin_psi*sin_theta + 3*I1_pitch*b*cos_psi*fb10*fb116*fb138*mu*sin_psi +
            3*I1_pitch*b*cos_theta*fb10*fb102*fb49*fb89*mu + 6*I1_pitch*b*cos_theta*fb10*fb107*
            fb49*mu*sin_phi + (3/2)*I1_pitch*b*cos_theta*fb10*mu*sin_phi + 9*I1_pitch*b*fb10*
            fb107*fb132*fb49*mu*sin_phi + 2*I1_pitch*cos_phi*fb49*nu_dot*sin_phi*theta_dot +
            I1_pitch*cos_phi*fb49*psi_dot*theta_dot + I1_pitch*cos_phi*fb52*nu_dot*psi_dot + 3*
            I1_roll*b*cos_psi*fb10*fb107*fb138*mu*sin_psi + 12*I1_roll*b*cos_psi*fb10*fb116*
            fb90*mu*sin_psi*sin_theta + 3*I1_roll*b*cos_psi*fb10*fb116*mu*sin_psi*sin_theta + 3*
            I1_roll*b*cos_theta*fb10*fb102*fb52*fb89*mu + 6*I1_roll*b*cos_theta*fb10*fb107*fb52*
            mu*sin_phi + (3/2)*I1_roll*b*cos_theta*fb10*mu*sin_phi + 9*I1_roll*b*fb10*fb107*
            fb132*fb52*mu*sin_phi + 3*I1_roll*cos_phi*cos_psi*cos_theta*fb6*mu*sin_psi*sin_theta +
            I1_roll*cos_phi*fb49*nu_dot*psi_dot + 2*I1_roll*cos_phi*fb52*nu_dot*sin_phi*theta_dot +
            I1_roll*cos_phi*fb52*psi_dot*theta_dot + 2*I1_roll*cos_psi*phi_dot*psi_dot*sin_psi -
            I1_roll*fb144*fb49 + 9*I1_yaw*b*cos_theta*fb10*fb102*fb107*mu*sin_phi + 3*I1_yaw*b*
            cos_theta*fb10*fb89*mu + (3/2)*I1_yaw*b*cos_theta*fb10*mu*sin_phi + I1_yaw*cos_phi*
            fb4*sin_phi + I1_yaw*cos_phi*fb47*sin_phi + 3*I1_yaw*cos_phi*fb6*fb90*mu*sin_phi +
            I1_yaw*cos_phi*nu_dot*psi_dot + 3*I2_pitch*a*cos_psi*fb10*fb107*fb138*mu*sin_psi + 12*
            I2_pitch*a*cos_psi*fb10*fb116*fb90*mu*sin_psi*sin_theta + 3*I2_pitch*a*cos_psi*fb10*
            fb116*mu*sin_psi*sin_theta + 6*I2_pitch*a*cos_theta*fb10*fb102*fb107*fb49*mu*sin_phi
            + (15/2)*I2_pitch*a*cos_theta*fb10*fb102*fb52*mu*sin_phi + 3*I2_pitch*a*cos_theta*
            fb10*fb49*fb89*mu + (9/2)*I2_pitch*a*fb10*fb132*fb49*fb89*mu + 2*I2_pitch*cos_phi*
            fb49*nu_dot*sin_phi*theta_dot + I2_pitch*cos_phi*fb49*psi_dot*theta_dot + I2_pitch*
            cos_phi*fb52*nu_dot*psi_dot - I2_pitch*fb39*fb42 + 12*I2_roll*a*cos_psi*fb10*fb107*
            fb90*mu*sin_psi*sin_theta + 3*I2_roll*a*cos_psi*fb10*fb107*mu*sin_psi*sin_theta + 3*
            I2_roll*a*cos_psi*fb10*fb116*fb138*mu*sin_psi + 6*I2_roll*a*cos_theta*fb10*fb102*
            fb107*fb52*mu*sin_phi + (15/2)*I2_roll*a*cos_theta*fb10*fb102*fb49*mu*sin_phi + 3*
            I2_roll*a*cos_theta*fb10*fb52*fb89*mu + (9/2)*I2_roll*a*fb10*fb132*fb52*fb89*mu + 3*
            I2_roll*cos_phi*cos_psi*cos_theta*fb6*mu*sin_psi*sin_theta + I2_roll*cos_phi*fb49*
            nu_dot*psi_dot + 2*I2_roll*cos_phi*fb52*nu_dot*sin_phi*theta_dot + I2_roll*cos_phi*fb52*
            psi_dot*theta_dot + 2*I2_roll*cos_psi*phi_dot*psi_dot*sin_psi + 6*I2_yaw*a*cos_theta*
            fb10*fb107*mu*sin_phi + (27/2)*I2_yaw*a*fb10*fb107*fb132*mu*sin_phi + I2_yaw*cos_phi*
            fb4*sin_phi + I2_yaw*cos_phi*fb47*sin_phi + 3*I2_yaw*cos_phi*fb6*fb90*mu*sin_phi +
            I2_yaw*cos_phi*nu_dot*psi_dot + (3/2)*J2*b*cos_theta*fb10*fb17*m1*mu*sin_phi + (3/2)*
            J2*cos_phi*fb102*fb14*fb17*fb79*m2*mu*sin_phi + (3/2)*J2*cos_phi*fb102*fb14*fb17*
            fb81*m1*mu*sin_phi + (45/4)*J2*cos_theta*fb102*fb107*fb111*fb17*fb20*m2*mu*sin_phi +
            (45/2)*J2*cos_theta*fb107*fb112*fb17*fb20*m1*mu*sin_phi + (45/4)*J2*cos_theta*fb111*
            fb17*fb20*fb89*m2*mu + 15*J2*fb107*fb112*fb132*fb17*fb20*m1*mu*sin_phi + Q_phi + a*
            cos_theta*fb4*m2*r*sin_phi + 2*a*m2*nu_dot*r_dot*sin_phi*sin_theta + b*cos_theta*
            fb25*m1*mu*sin_phi + cos_phi*fb102*fb6*fb79*m2*mu*sin_phi + cos_phi*fb102*fb6*fb81*
            m1*mu*sin_phi + 2*cos_phi*fb102*fb79*m2*nu_dot*sin_phi*theta_dot + 2*cos_phi*fb102*
            fb81*m1*nu_dot*sin_phi*theta_dot + cos_phi*fb79*fb80*m2*sin_phi + 2*cos_phi*fb79*fb90*
            m2*nu_dot*sin_phi*theta_dot + cos_phi*fb80*fb81*m1*sin_phi + 2*cos_phi*fb81*fb90*m1*
            nu_dot*sin_phi*theta_dot + (9/2)*cos_theta*fb10*fb102*fb107*fb111*m2*mu*sin_phi + 3*
            cos_theta*fb10*fb107*fb112*m1*mu*sin_phi + (3/2)*cos_theta*fb10*fb111*fb89*m2*mu +
            (9/2)*fb10*fb107*fb111*fb132*m2*mu*sin_phi - fb101*fb102 - fb101*fb90 - fb102*fb105 -
            fb102*fb126*fb176 - fb102*fb130*fb176 - fb102*fb146*fb171 - fb102*fb153*fb171 - fb102*
            fb155*fb156*fb76 - fb102*fb163*fb174*fb63 - fb103*fb69 - fb103*fb71 - fb104*fb177 -
            fb104*fb69 - fb104*fb71 - fb105*fb90 - fb106*fb69 - fb106*fb71 - 27/2*fb108*fb11*fb133*
            sin_phi - fb108*fb110 - fb113*fb174*fb92 - fb113*fb29*fb92 - fb115*fb117 - fb115*fb119 -
            fb116*fb140*fb145 - fb116*fb149*fb151 - fb117*fb168 - fb119*fb168 - fb120*fb121 - fb120*
            fb169 - fb121*fb123 - fb123*fb169 - fb125*fb76 - fb126*fb127 - fb126*fb133*fb162 - fb127*
            fb130 - fb128*fb129 - fb130*fb133*fb162 - fb131*fb72 - fb131*fb73 - fb131*fb74 - fb134*
            fb85 - fb134*fb88 - fb136*fb164*fb179 - fb136*fb178*fb63 - fb136*fb63*fb93 - fb137*fb140
            - fb141*fb144 - fb147*fb148 - fb147*fb170 - fb148*fb154 - fb151*fb152 - fb154*fb170 -
            fb160*fb83 - fb160*fb87 - fb161*fb163*fb164 - fb163*fb175*fb63 - fb177*fb99 - fb36*fb37 -
            fb37*fb38 - fb40*fb42 - fb43*fb45 - fb45*fb46 - fb48*fb51 - fb48*fb53 - fb48*fb98 - fb51*
            fb57 - fb53*fb57 - fb54*fb55 - fb54*fb58 - fb55*fb56 - fb56*fb58 - fb57*fb98 - fb59*fb62 -
            fb63*fb65 - fb67*fb68 - fb69*fb70 - fb69*fb72 - fb69*fb73 - fb69*fb74 - fb69*fb99 - fb70*
            fb71 - fb71*fb72 - fb71*fb73 - fb71*fb74 - fb71*fb99 - fb75*fb76 - fb76*fb77 - fb76*fb78 -
            fb85 - fb88 - fb91*fb94)
    B4 = (
            I1_pitch*fb203 - I1_roll*fb184 + I2_pitch*fb203 - I2_roll*fb184 + Q_theta + a*fb180*fb181 +
            fb108*fb97 - fb113*fb193 - fb113*fb231 - fb114*fb198 + fb114*fb205 + fb122*fb131 - fb122*
            fb197 - 39/2*fb129*fb165*fb251 + fb130*fb204 + fb131*fb145 - fb131*fb149 - fb131*fb40 +
            fb135*fb193 + fb135*fb231 - fb141*fb97 - fb145*fb197 + fb149*fb197 + fb153*fb204 + fb155*
            fb97 - fb181*fb65 + fb182*fb183 + fb183*fb194 + fb183*fb195 - fb183*fb67 - fb185*fb97 +
            fb188*fb189 - fb188*fb91 - fb190*fb75 - fb190*fb77 - fb191*fb192 + fb191*fb196 + fb197*
            fb40 - fb200*fb254 - fb200*fb97 - fb202*fb254 - fb202*fb97 - fb206*fb207 + fb207*fb223 -
            fb207*fb252 - fb208*fb209 + fb208*fb229 - fb209*fb210 + fb210*fb229 - fb212*fb213 + fb212*
            fb216 - fb213*fb250 - fb214*fb215 + fb214*fb248 + fb215*fb217 + fb216*fb250 - fb217*fb248 +
            fb218*fb220 + fb218*fb222 - fb220*fb224 - fb222*fb224 - fb225*fb70 - fb225*fb72 - fb226*
            fb73 - fb226*fb74 + fb227*fb70 + fb227*fb72 + fb228*fb73 + fb228*fb74 - fb232*fb233 +
            fb233*fb234 - fb235*fb241 + fb235*fb258 - fb236*fb238 + fb238*fb246 - fb239*fb240 + fb240*
            fb247 + fb241*fb244 - fb242*fb243 + fb242*fb259 + fb243*fb245 - fb244*fb258 - fb245*fb259 +
            fb256*fb73 + fb256*fb74 + fb286)
    B5 = (
            I1_roll*fb292 + I1_roll*fb294 - I2_pitch*fb292 + I2_roll*fb292 + I2_roll*fb294 + Q_psi +
            cos_theta*fb244*fb303*fb304 + cos_theta*fb247*fb310 - fb102*fb309 + fb102*fb311 + fb109*
            fb251*fb305 + fb116*fb302*fb303 + fb119*fb4 - fb119*fb45 + fb119*fb47 - fb120*fb4 + fb120*
            fb45 - fb120*fb47 - fb122*fb300 - fb126*fb293 + fb129*fb237*fb61 - fb130*fb293 - fb137*fb4
            + fb137*fb45 - fb137*fb47 + fb141*fb293 - fb145*fb300 - fb146*fb293 + fb149*fb300 + fb152*
            fb4 - fb152*fb45 + fb152*fb47 - fb153*fb293 + fb185*fb293 - fb208*fb295 + fb208*fb312 -
            fb208*fb317 - fb210*fb295 + fb210*fb312 - fb210*fb317 - fb220*fb314 - fb222*fb314 + fb236*
            fb315 + fb239*fb318 - fb246*fb315 - fb247*fb318 - fb251*fb302 - fb261 - fb262 + fb264 + fb266
            + fb267*fb36 + fb267*fb38 - fb269*fb36 - fb269*fb38 + fb271 + fb274 + fb276 + fb277 - fb279 -
            fb280 - fb281 - fb282 + fb287*fb48 + fb287*fb57 + fb288*fb55 + fb288*fb58 - fb289*fb48 -
            fb289*fb57 - fb290*fb55 - fb290*fb58 - fb291*fb40 + fb295*fb70 + fb295*fb72 + fb297*fb298
            + fb297*fb299 - fb297*fb73 - fb297*fb74 + fb298*fb319 + fb299*fb319 + fb300*fb40 - fb304*
            fb306 - fb306*fb308 - fb307*fb310 + fb309 - fb311 - fb312*fb70 - fb312*fb72 + fb313*fb73 +
            fb313*fb74 + fb317*fb72 - fb319*fb73 - fb319*fb74)
    B6 = (
            I1_roll*fb322 + I1_roll*fb336 - I1_yaw*fb29 + I2_roll*fb322 + I2_roll*fb336 + Q_r + fb108*
            fb323 - fb122*fb350 - fb124*m1 - fb125 + fb126*fb335 - fb139*fb235*fb359 + fb139*fb358*
            sin_phi + fb141*fb175 - fb145*fb350 + fb146*fb335 + fb149*fb350 + fb155*fb323 + fb175*fb185
            + fb180 - fb182 - fb192*fb326 - fb194 - fb195 + fb196*fb326 - fb198*fb337 + fb199*fb211 +
            fb199*fb249 - fb200*fb328 + fb200*fb334 - fb200*fb348 + fb200*fb356 + fb201*fb211 + fb201*
            fb249 - fb202*fb328 + fb202*fb334 - fb202*fb348 + fb202*fb356 + fb205*fb337 - fb206*fb325 +
            fb206*fb338 - fb208*fb343 - fb210*fb343 - fb213*fb339 - fb213*fb364 - fb214*fb327 - fb214*
            fb340 + fb216*fb339 + fb216*fb364 + fb217*fb327 + fb217*fb340 - fb219*fb326 + fb220*fb354 -
            fb221*fb326 + fb222*fb354 + fb223*fb325 - fb223*fb338 - fb232*fb321 + fb234*fb321 - fb239*
            fb360 - 3*fb24 + fb242*fb362 + fb242*fb367 - fb244*fb366*fb61 - fb245*fb362 - fb245*fb367
            + fb247*fb360 + fb251*fb338*fb70 + fb252*fb338 + fb268*fb330 - fb268*fb62 - fb270*fb330 +
            fb270*fb62 - fb278*fb329 - fb278*fb351 + fb278*fb45 - fb278*fb47 - fb278*fb80 - fb28*fb33
            - 45/2*fb28*fb341 + fb283*fb329 + fb283*fb351 - fb283*fb45 + fb283*fb47 + fb283*fb80 -
            fb31*fb33 - 135/2*fb31*fb341 - fb32*fb320 + 30*fb320*fb333 + fb331*fb48 + fb331*fb55 +
            fb34 - fb345*fb346 + fb345*fb365 + fb346*fb355 - fb347*fb70 - fb347*fb72 - fb349*fb70 -
            fb349*fb72 + fb350*fb40 + fb352*fb73 + fb352*fb74 + fb353*fb73 + fb353*fb74 - fb355*fb365
            + fb357*fb363 - fb358*fb61 - fb361*fb73 - fb361*fb74 + fb363*fb366 - fb64 + fb67 - fb75 -
            fb77 - fb78)
    B7 = (
            Q_nu + a*cos_phi*fb47*m2*r*sin_theta + a*cos_phi*fb80*m2*r*sin_theta + 2*a*cos_theta*
            m2*phi_dot*r*sin_phi*theta_dot + 2*b*cos_phi*m1*nu_dot*r*sin_theta*theta_dot + 2*b*
            cos_theta*m1*nu_dot*phi_dot*r*sin_phi - delta_x*fb27 - delta_y*fb2 - delta_y*fb3 - fb2*r
            - fb232*fb369*fb45 - fb268*fb368*fb68 - fb270*fb76*m2*r - fb286 - fb3*r - fb368*fb59 -
            fb370*fb47 - fb370*fb80 - fb59*m2*r)
    mm0 = delta_x*m3
    mm1 = sin_psi**2
    mm2 = cos_psi**2
    mm3 = a**2*m2
    mm4 = b**2*m1
    mm5 = a*m2
    mm6 = b*m1
    mm7 = mm5 - mm6
    mm8 = 2*psi
    mm9 = -sincos(mm8 - phi)[0]
    mm10 = (1/4)*mm9
    mm11 = sincos(mm8 + phi)[0]
    mm12 = (1/4)*mm11
    mm13 = sin_phi**2
    mm14 = cos_phi**2
    mm15 = mm14*mm2
    mm16 = mm1*mm14
    mm17 = (
            I1_pitch*mm15 + I1_roll*mm16 + I1_yaw*mm13 + I2_pitch*mm15 + I2_roll*mm16 + I2_yaw*mm13 +
            mm14*mm3 + mm14*mm4)
    mm18 = I1_yaw + I2_yaw
    mm19 = mm18*sin_phi
    mm20 = cos_phi*sin_theta
    mm21 = cos_phi*cos_theta
    mm22 = r**2
    mm23 = 2*r
    mm24 = mm21*mm23
    M0_0 = m3
    M0_1 = 0
    M0_2 = 0
    M0_3 = 0
    M0_4 = 0
    M0_5 = 0
    M0_6 = 0
    M0_7 = -m3*(delta_y + r)
    M1_1 = m3
    M1_2 = 0
    M1_3 = 0
    M1_4 = 0
    M1_5 = 0
    M1_6 = m3
    M1_7 = mm0
    M2_2 = m3
    M2_3 = 0
    M2_4 = 0
    M2_5 = 0
    M2_6 = 0
    M2_7 = 0
    M3_3 = I1_pitch*mm1 + I1_roll*mm2 + I2_pitch*mm1 + I2_roll*mm2 + mm3 + mm4
    M3_4 = cos_phi*cos_psi*sin_psi*(-I1_pitch + I1_roll - I2_pitch + I2_roll)
    M3_5 = 0
    M3_6 = cos_theta*mm7*sin_phi
    M3_7 = (
            -I1_pitch*mm10 + (1/4)*I1_pitch*mm11 - I1_roll*mm12 + (1/4)*I1_roll*mm9 - I2_pitch*mm10 +
            (1/4)*I2_pitch*mm11 - I2_roll*mm12 + (1/4)*I2_roll*mm9 + b*m1*r*sin_phi*sin_theta - mm5*
            r*sin_phi*sin_theta)
    M4_4 = mm17
    M4_5 = -mm19
    M4_6 = mm20*mm7
    M4_7 = a*cos_phi*cos_theta*m2*r - mm17 - mm21*mm6*r
    M5_5 = mm18
    M5_6 = 0
    M5_7 = mm19
    M6_6 = m1 + m2 + m3
    M6_7 = mm0 - mm20*mm5 + mm20*mm6
    M7_7 = (
            delta_x**2*m3 + delta_y**2*m3 + delta_y*m3*mm23 + m1*mm22 + m2*mm22 + m3*mm22 + mm17 -
            mm24*mm5 + mm24*mm6)
    if I1_yaw + I2_yaw == 0.0:  # no inertia about the boom: psi'' = 0 (docs/three-d.md)
        M0_5 = 0.0
        M1_5 = 0.0
        M2_5 = 0.0
        M3_5 = 0.0
        M4_5 = 0.0
        M5_6 = 0.0
        M5_7 = 0.0
        M5_5 = 1.0
        B5 = 0.0
    L1_0 = M0_1 / M0_0
    M1_1 -= L1_0 * M0_1
    M1_2 -= L1_0 * M0_2
    M1_3 -= L1_0 * M0_3
    M1_4 -= L1_0 * M0_4
    M1_5 -= L1_0 * M0_5
    M1_6 -= L1_0 * M0_6
    M1_7 -= L1_0 * M0_7
    L2_0 = M0_2 / M0_0
    M2_2 -= L2_0 * M0_2
    M2_3 -= L2_0 * M0_3
    M2_4 -= L2_0 * M0_4
    M2_5 -= L2_0 * M0_5
    M2_6 -= L2_0 * M0_6
    M2_7 -= L2_0 * M0_7
    L3_0 = M0_3 / M0_0
    M3_3 -= L3_0 * M0_3
    M3_4 -= L3_0 * M0_4
    M3_5 -= L3_0 * M0_5
    M3_6 -= L3_0 * M0_6
    M3_7 -= L3_0 * M0_7
    L4_0 = M0_4 / M0_0
    M4_4 -= L4_0 * M0_4
    M4_5 -= L4_0 * M0_5
    M4_6 -= L4_0 * M0_6
    M4_7 -= L4_0 * M0_7
    L5_0 = M0_5 / M0_0
    M5_5 -= L5_0 * M0_5
    M5_6 -= L5_0 * M0_6
    M5_7 -= L5_0 * M0_7
    L6_0 = M0_6 / M0_0
    M6_6 -= L6_0 * M0_6
    M6_7 -= L6_0 * M0_7
    L7_0 = M0_7 / M0_0
    M7_7 -= L7_0 * M0_7
    L2_1 = M1_2 / M1_1
    M2_2 -= L2_1 * M1_2
    M2_3 -= L2_1 * M1_3
    M2_4 -= L2_1 * M1_4
    M2_5 -= L2_1 * M1_5
    M2_6 -= L2_1 * M1_6
    M2_7 -= L2_1 * M1_7
    L3_1 = M1_3 / M1_1
    M3_3 -= L3_1 * M1_3
    M3_4 -= L3_1 * M1_4
    M3_5 -= L3_1 * M1_5
    M3_6 -= L3_1 * M1_6
    M3_7 -= L3_1 * M1_7
    L4_1 = M1_4 / M1_1
    M4_4 -= L4_1 * M1_4
    M4_5 -= L4_1 * M1_5
    M4_6 -= L4_1 * M1_6
    M4_7 -= L4_1 * M1_7
    L5_1 = M1_5 / M1_1
    M5_5 -= L5_1 * M1_5
    M5_6 -= L5_1 * M1_6
    M5_7 -= L5_1 * M1_7
    L6_1 = M1_6 / M1_1
    M6_6 -= L6_1 * M1_6
    M6_7 -= L6_1 * M1_7
    L7_1 = M1_7 / M1_1
    M7_7 -= L7_1 * M1_7
    L3_2 = M2_3 / M2_2
    M3_3 -= L3_2 * M2_3
    M3_4 -= L3_2 * M2_4
    M3_5 -= L3_2 * M2_5
    M3_6 -= L3_2 * M2_6
    M3_7 -= L3_2 * M2_7
    L4_2 = M2_4 / M2_2
    M4_4 -= L4_2 * M2_4
    M4_5 -= L4_2 * M2_5
    M4_6 -= L4_2 * M2_6
    M4_7 -= L4_2 * M2_7
    L5_2 = M2_5 / M2_2
    M5_5 -= L5_2 * M2_5
    M5_6 -= L5_2 * M2_6
    M5_7 -= L5_2 * M2_7
    L6_2 = M2_6 / M2_2
    M6_6 -= L6_2 * M2_6
    M6_7 -= L6_2 * M2_7
    L7_2 = M2_7 / M2_2
    M7_7 -= L7_2 * M2_7
    L4_3 = M3_4 / M3_3
    M4_4 -= L4_3 * M3_4
    M4_5 -= L4_3 * M3_5
    M4_6 -= L4_3 * M3_6
    M4_7 -= L4_3 * M3_7
    L5_3 = M3_5 / M3_3
    M5_5 -= L5_3 * M3_5
    M5_6 -= L5_3 * M3_6
    M5_7 -= L5_3 * M3_7
    L6_3 = M3_6 / M3_3
    M6_6 -= L6_3 * M3_6
    M6_7 -= L6_3 * M3_7
    L7_3 = M3_7 / M3_3
    M7_7 -= L7_3 * M3_7
    L5_4 = M4_5 / M4_4
    M5_5 -= L5_4 * M4_5
    M5_6 -= L5_4 * M4_6
    M5_7 -= L5_4 * M4_7
    L6_4 = M4_6 / M4_4
    M6_6 -= L6_4 * M4_6
    M6_7 -= L6_4 * M4_7
    L7_4 = M4_7 / M4_4
    M7_7 -= L7_4 * M4_7
    L6_5 = M5_6 / M5_5
    M6_6 -= L6_5 * M5_6
    M6_7 -= L6_5 * M5_7
    L7_5 = M5_7 / M5_5
    M7_7 -= L7_5 * M5_7
    L7_6 = M6_7 / M6_6
    M7_7 -= L7_6 * M6_7
    B1 -= L1_0 * B0
    B2 -= L2_0 * B0
    B3 -= L3_0 * B0
    B4 -= L4_0 * B0
    B5 -= L5_0 * B0
    B6 -= L6_0 * B0
    B7 -= L7_0 * B0
    B2 -= L2_1 * B1
    B3 -= L3_1 * B1
    B4 -= L4_1 * B1
    B5 -= L5_1 * B1
    B6 -= L6_1 * B1
    B7 -= L7_1 * B1
    B3 -= L3_2 * B2
    B4 -= L4_2 * B2
    B5 -= L5_2 * B2
    B6 -= L6_2 * B2
    B7 -= L7_2 * B2
    B4 -= L4_3 * B3
    B5 -= L5_3 * B3
    B6 -= L6_3 * B3
    B7 -= L7_3 * B3
    B5 -= L5_4 * B4
    B6 -= L6_4 * B4
    B7 -= L7_4 * B4
    B6 -= L6_5 * B5
    B7 -= L7_5 * B5
    B7 -= L7_6 * B6
    X7 = (B7) / M7_7
    X6 = (B6 - M6_7 * X7) / M6_6
    X5 = (B5 - M5_6 * X6 - M5_7 * X7) / M5_5
    X4 = (B4 - M4_5 * X5 - M4_6 * X6 - M4_7 * X7) / M4_4
    X3 = (B3 - M3_4 * X4 - M3_5 * X5 - M3_6 * X6 - M3_7 * X7) / M3_3
    X2 = (B2 - M2_3 * X3 - M2_4 * X4 - M2_5 * X5 - M2_6 * X6 - M2_7 * X7) / M2_2
    X1 = (B1 - M1_2 * X2 - M1_3 * X3 - M1_4 * X4 - M1_5 * X5 - M1_6 * X6 - M1_7 * X7) / M1_1
    X0 = (B0 - M0_1 * X1 - M0_2 * X2 - M0_3 * X3 - M0_4 * X4 - M0_5 * X5 - M0_6 * X6 - M0_7 * X7) / M0_0
    dydt[0] = delta_x_dot
    dydt[1] = delta_y_dot
    dydt[2] = delta_z_dot
    dydt[3] = phi_dot
    dydt[4] = theta_dot
    dydt[5] = psi_dot
    dydt[6] = r_dot
    dydt[7] = nu_dot
    dydt[8] = X0
    dydt[9] = X1
    dydt[10] = X2
    dydt[11] = X3
    dydt[12] = X4
    dydt[13] = X5
    dydt[14] = X6
    dydt[15] = X7


@njit(cache=True)
def family_forces(y, p, out):
    """out[f, k] = generalized force of family FAMILIES[f] on q_k (N, N, N, N m, N m, N m, N, N m)."""
    delta_x = y[0]
    delta_y = y[1]
    delta_z = y[2]
    phi = y[3]
    theta = y[4]
    r = y[6]
    delta_x_dot = y[8]
    delta_y_dot = y[9]
    delta_z_dot = y[10]
    phi_dot = y[11]
    theta_dot = y[12]
    r_dot = y[14]
    nu_dot = y[15]
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
    sin_phi, cos_phi = sincos(phi)
    sin_theta, cos_theta = sincos(theta)
    lambda1 = (
            math.sqrt((b*sin_phi - delta_z)**2 + (b*cos_phi*cos_theta - delta_y)**2 + (b*cos_phi*
            sin_theta - delta_x)**2))
    lambda2 = (
            math.sqrt((-a*sin_phi - delta_z)**2 + (-a*cos_phi*cos_theta - delta_y)**2 + (-a*cos_phi*
            sin_theta - delta_x)**2))
    out[:, :] = 0.0
    # drag1: air drag on the tip-mass (3.32-3.34)
    f0_0 = b**2*cos_phi**2
    f0_1 = b*cos_phi
    f0_2 = f0_1*sin_theta
    f0_3 = b*sin_phi
    f0_4 = f0_3*phi_dot
    f0_5 = b*cos_phi*nu_dot*sin_theta - cos_theta*f0_4 - f0_2*omega_earth - f0_2*theta_dot + r_dot
    f0_6 = cos_theta*f0_1
    f0_7 = f0_6 + r
    f0_8 = -f0_4*sin_theta + f0_6*theta_dot - f0_7*nu_dot + f0_7*omega_earth
    f0_9 = math.sqrt(f0_0*phi_dot**2 + f0_5**2 + f0_8**2)
    f0_10 = (1/2)*A1*CD*f0_9*rho1
    f0_11 = f0_10*f0_5
    f0_12 = f0_10*f0_8
    f0_13 = f0_11*f0_2
    out[0, 0] = 0
    out[0, 1] = 0
    out[0, 2] = 0
    out[0, 3] = cos_theta*f0_11*f0_3 - f0_0*f0_10*phi_dot + f0_12*f0_3*sin_theta
    out[0, 4] = -f0_12*f0_6 + f0_13
    out[0, 5] = 0
    out[0, 6] = -f0_11
    out[0, 7] = (1/2)*A1*CD*f0_7*f0_8*f0_9*rho1 - f0_13
    # drag2: air drag on the main bus (3.32-3.34)
    f1_0 = a**2*cos_phi**2
    f1_1 = a*cos_phi
    f1_2 = f1_1*sin_theta
    f1_3 = a*sin_phi
    f1_4 = cos_theta*f1_3*phi_dot - f1_2*nu_dot + f1_2*omega_earth + f1_2*theta_dot + r_dot
    f1_5 = cos_theta*f1_1
    f1_6 = -f1_5 + r
    f1_7 = a*phi_dot*sin_phi*sin_theta - f1_5*theta_dot - f1_6*nu_dot + f1_6*omega_earth
    f1_8 = (1/2)*A2*CD*rho2*math.sqrt(f1_0*phi_dot**2 + f1_4**2 + f1_7**2)
    f1_9 = f1_4*f1_8
    f1_10 = f1_7*f1_8
    f1_11 = f1_2*f1_9
    out[1, 0] = 0
    out[1, 1] = 0
    out[1, 2] = 0
    out[1, 3] = -cos_theta*f1_3*f1_9 - f1_0*f1_8*phi_dot - f1_10*f1_3*sin_theta
    out[1, 4] = f1_10*f1_5 - f1_11
    out[1, 5] = 0
    out[1, 6] = -f1_9
    out[1, 7] = f1_10*f1_6 + f1_11
    # drag3: air drag on the balloon (3.32-3.34)
    f2_0 = delta_y + r
    f2_1 = delta_x_dot - f2_0*nu_dot + f2_0*omega_earth
    f2_2 = delta_x*nu_dot - delta_x*omega_earth + delta_y_dot + r_dot
    f2_3 = math.sqrt(delta_z_dot**2 + f2_1**2 + f2_2**2)
    f2_4 = (1/2)*A3*CD*f2_3*rho3
    f2_5 = f2_2*f2_4
    f2_6 = -f2_5
    out[2, 0] = -f2_1*f2_4
    out[2, 1] = f2_6
    out[2, 2] = -delta_z_dot*f2_4
    out[2, 3] = 0
    out[2, 4] = 0
    out[2, 5] = 0
    out[2, 6] = f2_6
    out[2, 7] = (1/2)*A3*CD*f2_0*f2_1*f2_3*rho3 - delta_x*f2_5
    # spring1: tension of tether 1 (3.35-3.42)
    if lambda1 > l10:
        f3_0 = 1/l10
        f3_1 = E1*delta_x
        f3_2 = f3_0*f3_1
        f3_3 = 1/lambda1
        f3_4 = E1*b
        f3_5 = cos_phi*f3_4
        f3_6 = E1*delta_y*f3_0
        f3_7 = E1*delta_z
        f3_8 = b*cos_phi
        f3_9 = b*sin_phi
        f3_10 = b**2
        f3_11 = E1*cos_phi*f3_10*sin_phi
        f3_12 = cos_theta**2
        f3_13 = f3_11*f3_3
        f3_14 = sin_theta**2
        out[3, 0] = E1*b*cos_phi*f3_0*sin_theta + E1*delta_x*f3_3 - f3_2 - f3_3*f3_5*sin_theta
        out[3, 1] = E1*b*cos_phi*cos_theta*f3_0 + E1*delta_y*f3_3 - cos_theta*f3_3*f3_5 - f3_6
        out[3, 2] = E1*b*f3_0*sin_phi + E1*delta_z*f3_3 - f3_0*f3_7 - f3_3*f3_4*sin_phi
        out[3, 3] = (
                E1*b*cos_phi*delta_z*f3_0 + E1*b*cos_theta*delta_y*f3_3*sin_phi + E1*b*delta_x*
                f3_3*sin_phi*sin_theta + E1*cos_phi*f3_0*f3_10*f3_12*sin_phi + E1*cos_phi*f3_0*
                f3_10*f3_14*sin_phi + E1*cos_phi*f3_10*f3_3*sin_phi - cos_theta*f3_6*f3_9 - f3_0*
                f3_11 - f3_12*f3_13 - f3_13*f3_14 - f3_2*f3_9*sin_theta - f3_3*f3_7*f3_8)
        out[3, 4] = (
                E1*b*cos_phi*cos_theta*delta_x*f3_0 + E1*b*cos_phi*delta_y*f3_3*sin_theta -
                cos_theta*f3_1*f3_3*f3_8 - f3_6*f3_8*sin_theta)
        out[3, 5] = 0
        out[3, 6] = 0
        out[3, 7] = 0
    # spring2: tension of tether 2 (3.36-3.42)
    if lambda2 > l20:
        f4_0 = 1/lambda2
        f4_1 = E2*delta_x
        f4_2 = f4_0*f4_1
        f4_3 = 1/l20
        f4_4 = f4_1*f4_3
        f4_5 = E2*a
        f4_6 = cos_phi*f4_5
        f4_7 = f4_6*sin_theta
        f4_8 = E2*delta_y
        f4_9 = f4_0*f4_8
        f4_10 = f4_3*f4_8
        f4_11 = cos_theta*f4_6
        f4_12 = E2*delta_z
        f4_13 = f4_12*f4_3
        f4_14 = f4_5*sin_phi
        f4_15 = a*cos_phi
        f4_16 = a*sin_phi
        f4_17 = a**2
        f4_18 = E2*cos_phi*f4_17*sin_phi
        f4_19 = cos_theta**2
        f4_20 = f4_0*f4_18
        f4_21 = sin_theta**2
        f4_22 = cos_theta*f4_15
        f4_23 = f4_15*sin_theta
        out[4, 0] = f4_0*f4_7 + f4_2 - f4_3*f4_7 - f4_4
        out[4, 1] = f4_0*f4_11 - f4_10 - f4_11*f4_3 + f4_9
        out[4, 2] = f4_0*f4_12 + f4_0*f4_14 - f4_13 - f4_14*f4_3
        out[4, 3] = (
                E2*a*cos_phi*delta_z*f4_0 + E2*a*cos_theta*delta_y*f4_3*sin_phi + E2*a*delta_x*
                f4_3*sin_phi*sin_theta + E2*cos_phi*f4_0*f4_17*sin_phi + E2*cos_phi*f4_17*f4_19*
                f4_3*sin_phi + E2*cos_phi*f4_17*f4_21*f4_3*sin_phi - cos_theta*f4_16*f4_9 - f4_13*
                f4_15 - f4_16*f4_2*sin_theta - f4_18*f4_3 - f4_19*f4_20 - f4_20*f4_21)
        out[4, 4] = f4_10*f4_23 + f4_2*f4_22 - f4_22*f4_4 - f4_23*f4_9
        out[4, 5] = 0
        out[4, 6] = 0
        out[4, 7] = 0
    # damper1: damping of tether 1 along its stretch rate (variant (issue 5))
    if lambda1 > l10:
        f5_0 = 1/lambda1
        f5_1 = c1*f5_0
        f5_2 = b*sin_phi
        f5_3 = b*cos_phi
        f5_4 = cos_theta*f5_3
        f5_5 = f5_3*sin_theta
        f5_6 = f5_1*phi_dot
        f5_7 = b**2
        f5_8 = cos_theta**2
        f5_9 = cos_phi*f5_7*sin_phi
        f5_10 = f5_6*f5_9
        f5_11 = sin_theta**2
        f5_12 = (
                f5_0*max(E1 - E1*lambda1/l10, b*c1*cos_phi*delta_y*f5_0*sin_theta*theta_dot + b*c1*
                cos_theta*delta_y*f5_0*phi_dot*sin_phi + b*c1*delta_x*f5_0*phi_dot*sin_phi*
                sin_theta + c1*cos_phi*f5_0*f5_7*phi_dot*sin_phi + c1*delta_x*delta_x_dot*f5_0 + c1*
                delta_y*delta_y_dot*f5_0 + c1*delta_z*delta_z_dot*f5_0 - delta_x*f5_1*f5_4*theta_dot
                - delta_x_dot*f5_1*f5_5 - delta_y_dot*f5_1*f5_4 - delta_z*f5_3*f5_6 - delta_z_dot*
                f5_1*f5_2 - f5_10*f5_11 - f5_10*f5_8))
        f5_13 = delta_x*f5_12
        f5_14 = f5_12*f5_3
        f5_15 = delta_y*f5_12
        f5_16 = delta_z*f5_12
        f5_17 = f5_12*f5_9
        out[5, 0] = -f5_13 + f5_14*sin_theta
        out[5, 1] = cos_theta*f5_14 - f5_15
        out[5, 2] = f5_12*f5_2 - f5_16
        out[5, 3] = (
                -cos_theta*f5_15*f5_2 + f5_11*f5_17 - f5_13*f5_2*sin_theta + f5_16*f5_3 + f5_17*f5_8 -
                f5_17)
        out[5, 4] = f5_13*f5_4 - f5_15*f5_5
        out[5, 5] = 0
        out[5, 6] = 0
        out[5, 7] = 0
    # damper2: damping of tether 2 along its stretch rate (variant (issue 5))
    if lambda2 > l20:
        f6_0 = 1/lambda2
        f6_1 = c2*f6_0
        f6_2 = delta_x_dot*f6_1
        f6_3 = delta_y_dot*f6_1
        f6_4 = delta_z_dot*f6_1
        f6_5 = a*sin_phi
        f6_6 = a*cos_phi
        f6_7 = cos_theta*f6_6
        f6_8 = f6_6*sin_theta
        f6_9 = f6_1*phi_dot
        f6_10 = f6_1*theta_dot
        f6_11 = a**2*cos_phi*sin_phi
        f6_12 = f6_11*f6_9
        f6_13 = cos_theta*f6_5
        f6_14 = f6_5*sin_theta
        f6_15 = cos_theta**2
        f6_16 = sin_theta**2
        f6_17 = (
                max(E2 - E2*lambda2/l20, delta_x*f6_10*f6_7 - delta_x*f6_14*f6_9 + delta_x*f6_2 -
                delta_y*f6_10*f6_8 - delta_y*f6_13*f6_9 + delta_y*f6_3 + delta_z*f6_4 + delta_z*f6_6*
                f6_9 - f6_12*f6_15 - f6_12*f6_16 + f6_12 + f6_2*f6_8 + f6_3*f6_7 + f6_4*f6_5))
        f6_18 = f6_0*f6_17
        f6_19 = delta_x*f6_18
        f6_20 = f6_18*f6_6
        f6_21 = delta_y*f6_18
        f6_22 = delta_z*f6_18
        f6_23 = f6_11*f6_18
        out[6, 0] = -f6_19 - f6_20*sin_theta
        out[6, 1] = -cos_theta*f6_20 - f6_21
        out[6, 2] = -f6_18*f6_5 - f6_22
        out[6, 3] = f6_13*f6_21 + f6_14*f6_19 + f6_15*f6_23 + f6_16*f6_23 - f6_22*f6_6 - f6_23
        out[6, 4] = a*cos_phi*delta_y*f6_0*f6_17*sin_theta - f6_19*f6_7
        out[6, 5] = 0
        out[6, 6] = 0
        out[6, 7] = 0


@njit(cache=True)
def jacobi(y, p):
    """Total energy T + V (orbit and attitude) plus taut-tether spring energy [J].

    L = T − V has no explicit t, so this is the Jacobi integral: constant with drag
    and dampers off, otherwise dE/dt = Σ_k (Q_drag + Q_damper)_k q̇_k.
    """
    delta_x = y[0]
    delta_y = y[1]
    delta_z = y[2]
    phi = y[3]
    theta = y[4]
    psi = y[5]
    r = y[6]
    delta_x_dot = y[8]
    delta_y_dot = y[9]
    delta_z_dot = y[10]
    phi_dot = y[11]
    theta_dot = y[12]
    psi_dot = y[13]
    r_dot = y[14]
    nu_dot = y[15]
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
    I1_roll = p[22]
    I1_pitch = p[23]
    I1_yaw = p[24]
    I2_roll = p[25]
    I2_pitch = p[26]
    I2_yaw = p[27]
    sin_phi, cos_phi = sincos(phi)
    sin_theta, cos_theta = sincos(theta)
    sin_psi, cos_psi = sincos(psi)
    e0 = delta_y_dot*m3
    e1 = I1_yaw*nu_dot
    e2 = psi_dot*sin_phi
    e3 = I2_yaw*nu_dot
    e4 = delta_x*nu_dot
    e5 = (1/2)*psi_dot**2
    e6 = (1/2)*m3
    e7 = (1/2)*r_dot**2
    e8 = e2*theta_dot
    e9 = delta_y*m3
    e10 = delta_x_dot*nu_dot
    e11 = mu/r**3
    e12 = (1/2)*I1_pitch
    e13 = (1/2)*e11
    e14 = mu/r
    e15 = r**2
    e16 = mu/e15
    e17 = nu_dot**2
    e18 = e17*r
    e19 = I1_pitch*nu_dot
    e20 = cos_psi*sin_psi
    e21 = cos_phi*e20
    e22 = e21*phi_dot
    e23 = e22*theta_dot
    e24 = e22*nu_dot
    e25 = sin_theta*theta_dot
    e26 = a*cos_phi
    e27 = m2*r_dot
    e28 = e26*e27
    e29 = phi_dot*sin_phi
    e30 = a*cos_theta
    e31 = nu_dot*sin_theta
    e32 = b*m1
    e33 = cos_phi*e32
    e34 = e33*r_dot
    e35 = sin_phi**2
    e36 = e35*theta_dot
    e37 = e29*e32
    e38 = e26*m2
    e39 = cos_theta*nu_dot*r*theta_dot
    e40 = e31*r
    e41 = (1/2)*phi_dot**2
    e42 = sin_psi**2
    e43 = I1_pitch*e42
    e44 = cos_psi**2
    e45 = e41*e44
    e46 = (1/2)*e35
    e47 = I1_yaw*e46
    e48 = theta_dot**2
    e49 = I2_pitch*e42
    e50 = I2_yaw*e46
    e51 = delta_x**2
    e52 = e17*e6
    e53 = delta_y**2
    e54 = e15*e17
    e55 = (1/2)*m1
    e56 = (1/2)*m2
    e57 = cos_theta*e16
    e58 = cos_theta*e18
    e59 = e11*e6
    e60 = e53*m3
    e61 = mu/r**4
    e62 = (3/2)*e61
    e63 = delta_y**3*m3
    e64 = delta_z**2
    e65 = cos_theta*e62
    e66 = cos_phi*e65
    e67 = I1_pitch*b
    e68 = I1_roll*b
    e69 = I1_yaw*b
    e70 = e26*e65
    e71 = cos_phi**2
    e72 = e71*theta_dot
    e73 = I1_roll*e42
    e74 = e72*nu_dot
    e75 = I2_pitch*e44
    e76 = I2_roll*e42
    e77 = J2*R_E**2
    e78 = e11*e77
    e79 = e62*e9
    e80 = e17*e71
    e81 = e12*e44
    e82 = e48*e71
    e83 = (1/2)*e80
    e84 = (1/2)*e82
    e85 = e41*e71
    e86 = a**2
    e87 = e86*m2
    e88 = b**2
    e89 = e88*m1
    e90 = 3*cos_theta
    e91 = sin_phi*sin_theta
    e92 = e11*e20*e90*e91
    e93 = (3/2)*e11
    e94 = sin_theta**2
    e95 = e43*e94
    e96 = e93*e94
    e97 = e44*e96
    e98 = cos_theta**2
    e99 = e93*e98
    e100 = e71*e99
    e101 = e11*e46
    e102 = cos_phi*e35
    e103 = e61*e69
    e104 = e103*e90
    e105 = I2_yaw*e61
    e106 = 3*e105
    e107 = e26*e35
    e108 = cos_theta*e107
    e109 = 3*e21*e61
    e110 = e109*e91
    e111 = I2_pitch*a
    e112 = I2_roll*a
    e113 = cos_phi**3
    e114 = cos_theta**3
    e115 = e113*e114
    e116 = (9/2)*e115
    e117 = e77*mu
    e118 = e117/r**5
    e119 = e118*m3
    e120 = 3*e118
    e121 = e117/r**6
    e122 = 5*e121
    e123 = e87*e98
    e124 = e74*e94
    e125 = e89*e98
    e126 = e65*e77
    e127 = e80*e98
    e128 = e56*e86
    e129 = e128*e82
    e130 = e80*e94
    e131 = e35*e41
    e132 = e131*e94
    e133 = e55*e88
    e134 = e133*e82
    e135 = e113*e94
    e136 = e121*e9
    e137 = a**3*m2
    e138 = e35*e66
    e139 = b**3*m1
    e140 = e109*sin_phi*sin_theta**3
    e141 = e35*e99
    e142 = e11*e71
    e143 = e142*e94
    e144 = e115*e62
    e145 = e102*e90
    e146 = e44*e61
    e147 = e146*e67
    e148 = e145*e147
    e149 = b*e61
    e150 = (15/2)*cos_theta
    e151 = cos_phi*e150
    e152 = e146*e94
    e153 = e149*e73
    e154 = e145*e153
    e155 = e61*e75
    e156 = 3*e108
    e157 = e155*e156
    e158 = e150*e26
    e159 = e61*e76
    e160 = e156*e159
    e161 = 12*e21*e61*e91*e98
    e162 = (9/4)*e35
    e163 = e118*e87
    e164 = e118*e89
    e165 = e135*e65
    e166 = (9/2)*e114
    e167 = e102*e166
    e168 = e107*e166
    e169 = (45/4)*e102
    e170 = cos_theta*e121
    e171 = e137*e170
    e172 = e139*e170
    e173 = e120*e71
    e174 = (3/4)*e71*e94
    e175 = e115*e122
    e176 = (15/4)*e135
    h = (
            I1_pitch*e141*e44 - I1_pitch*e23 + I1_pitch*e92 - I1_roll*e13 + I1_roll*e23 - I1_roll*e24
            + I1_roll*e45 - I1_roll*e92 + I1_roll*e97 + I1_yaw*e100 - I1_yaw*e13 + I1_yaw*e5 - I1_yaw*
            e8 - I2_pitch*e13 - I2_pitch*e23 + I2_pitch*e24 - I2_pitch*e70 + I2_pitch*e92 - I2_roll*e13
            + I2_roll*e152*e158 + I2_roll*e23 - I2_roll*e24 + I2_roll*e45 - I2_roll*e70 - I2_roll*e92
            + I2_roll*e97 + I2_yaw*e100 - I2_yaw*e13 + I2_yaw*e5 - I2_yaw*e70 - I2_yaw*e8 + a*e105*
            e116 - a*e29*e40*m2 - cos_theta*e37*r_dot + delta_x_dot**2*e6 + delta_y_dot**2*e6 +
            delta_z_dot**2*e6 + e0*e4 + e0*r_dot + e1*e2 - e1*e36 - e10*e9 - e10*m3*r + e101*e87 +
            e101*e89 + e102*e104 - e103*e116 + e104*e135 - e106*e108 - e106*e135*e30 - e11*e12 - e11*
            e60 + e110*e111 - e110*e112 - e110*e67 + e110*e68 - e111*e140 + e111*e161 + e112*e140 -
            e112*e161 + (3/4)*e119*e51 + (9/4)*e119*e64 - e120*e60 + e122*e63 + e123*e131 - e123*
            e142 - e123*e173 - e123*e74 - e124*e87 - e124*e89 + e125*e131 - e125*e142 - e125*e173 -
            e125*e74 + e126*e33 - e126*e38 + e127*e128 + e127*e133 + e128*e130 + e128*e143 + e129*e94
            + e129*e98 + e130*e133 + e132*e87 + e132*e89 + e133*e143 + e134*e94 + e134*e98 - 15/4*
            e136*e51 - 45/4*e136*e64 + e137*e138 + e137*e144 + e137*e165 - e137*e175 - e138*e139 -
            e139*e144 - e139*e165 + e139*e175 - e14*m1 - e14*m2 - e14*m3 + e140*e67 - e140*e68 +
            e141*e73 + e141*e75 + e141*e76 - e147*e167 + e148*e94 - e148 - e149*e151*e95 - e151*e152*
            e68 - e153*e167 + e154*e94 - e154 + e155*e168 - e157*e94 + e157 + e158*e49*e61*e94 + e159*
            e168 + e16*e9 - e160*e94 + e160 - e161*e67 + e161*e68 + e162*e163 + e162*e164 + e163*e174
            + e164*e174 + e169*e171 - e169*e172 + e17*e47 + e17*e50 + e171*e176 - e172*e176 + e18*e9
            + e19*e22 - e19*e44*e72 + e2*e3 + e25*e28 - e25*e34 + e27*e29*e30 - e28*e31 - e3*e36 +
            e31*e34 - e33*e39 + e33*e57 + e33*e58 + e37*e40 + e38*e39 - e38*e57 - e38*e58 + e4*m3*
            r_dot + e41*e43 + e41*e49 + e47*e48 + e48*e50 + e49*e96 + e51*e52 + e51*e59 - e51*e79 +
            e52*e53 + e54*e55 + e54*e56 + e54*e6 - e55*e78 - e56*e78 + e59*e64 - e59*e77 - e62*e63 -
            e64*e79 + e66*e67 + e66*e68 + e66*e69 + e7*m1 + e7*m2 + e7*m3 - e73*e74 + e73*e83 + e73*
            e84 - e74*e75 - e74*e76 + e75*e83 + e75*e84 + e76*e83 + e76*e84 + e77*e79 + e80*e81 +
            e81*e82 + e85*e87 + e85*e89 + e93*e95)
    lambda1 = (
            math.sqrt((b*sin_phi - delta_z)**2 + (b*cos_phi*cos_theta - delta_y)**2 + (b*cos_phi*
            sin_theta - delta_x)**2))
    if lambda1 > l10:
        h += (1/2)*E1*(-l10 + lambda1)**2/l10
    lambda2 = (
            math.sqrt((-a*sin_phi - delta_z)**2 + (-a*cos_phi*cos_theta - delta_y)**2 + (-a*cos_phi*
            sin_theta - delta_x)**2))
    if lambda2 > l20:
        h += (1/2)*E2*(-l20 + lambda2)**2/l20
    return h


@njit(cache=True, inline="always")
def tether_margins(y, p, g):
    """g[j] = λ_j − l_j0 [m]: tether j is taut when g[j] > 0 (Eqs 3.39-3.42)."""
    delta_x = y[0]
    delta_y = y[1]
    delta_z = y[2]
    phi = y[3]
    theta = y[4]
    a = p[6]
    b = p[7]
    l10 = p[8]
    l20 = p[9]
    sin_phi, cos_phi = sincos(phi)
    sin_theta, cos_theta = sincos(theta)
    g[0] = (
            math.sqrt((b*cos_phi*sin_theta - delta_x)**2 + (b*cos_phi*cos_theta - delta_y)**2 + (b*
            sin_phi - delta_z)**2) - l10)
    g[1] = (
            math.sqrt((-a*cos_phi*sin_theta - delta_x)**2 + (-a*cos_phi*cos_theta - delta_y)**2 + (-a*
            sin_phi - delta_z)**2) - l20)


@njit(cache=True, inline="always")
def body_radii(y, p):
    """(|R_1|, |R_2|, |R_3|) [m]: tip-mass, bus, balloon from Earth's centre.

    Positions (docs/three-d.md, about the orbit radius r).
    """
    delta_x = y[0]
    delta_y = y[1]
    delta_z = y[2]
    phi = y[3]
    theta = y[4]
    r = y[6]
    a = p[6]
    b = p[7]
    sin_phi, cos_phi = sincos(phi)
    sin_theta, cos_theta = sincos(theta)
    return (
            math.sqrt((b*cos_phi*sin_theta)**2 + (b*cos_phi*cos_theta + r)**2 + (b*sin_phi)**2),
            math.sqrt((-a*cos_phi*sin_theta)**2 + (-a*cos_phi*cos_theta + r)**2 + (-a*sin_phi)**2),
            math.sqrt((delta_x)**2 + (delta_y + r)**2 + (delta_z)**2))
