"""GENERATED FILE - DO NOT EDIT.

Model '3d-exact-gravity': 3-D model with exact point-mass gravity and MacCullagh box terms (no expansion, no
truncation), thesis dampers.
Produced by `make derive` (python -m derive) from derive/three_d/; regenerate
instead of editing.  sympy 1.14.0.  Conventions: docs/three-d.md.

State vector y (index, name, unit, meaning):
   0  delta_x      m         balloon offset along x (wake)
   1  delta_y      m         balloon offset along y (radially up)
   2  delta_z      m         balloon offset along z (orbit normal)
   3  phi          rad       roll of the boom (about pitched x)
   4  theta        rad       pitch of the boom (planar theta)
   5  psi          rad       yaw of the boom (about the boom axis)
   6  delta_x_dot  m/s       rate of balloon offset along x (wake)
   7  delta_y_dot  m/s       rate of balloon offset along y (radially up)
   8  delta_z_dot  m/s       rate of balloon offset along z (orbit normal)
   9  phi_dot      rad/s     rate of roll of the boom (about pitched x)
  10  theta_dot    rad/s     rate of pitch of the boom (planar theta)
  11  psi_dot      rad/s     rate of yaw of the boom (about the boom axis)

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

MODEL = '3d-exact-gravity'
DESCRIPTION = (
    '3-D model with exact point-mass gravity and MacCullagh box terms (no expansion, no truncation), thesis '
    'dampers'
)
GEOMETRY = "3d"  # roll, pitch, yaw and an out-of-plane balloon
ORBIT = "circular"  # the COM held on a circle of radius r0 at rate ω
STATE = (
    'delta_x', 'delta_y', 'delta_z', 'phi', 'theta', 'psi', 'delta_x_dot', 'delta_y_dot', 'delta_z_dot',
    'phi_dot', 'theta_dot', 'psi_dot',
)
STATE_UNITS = ('m', 'm', 'm', 'rad', 'rad', 'rad', 'm/s', 'm/s', 'm/s', 'rad/s', 'rad/s', 'rad/s')
PARAMETERS = (
    'm1', 'm2', 'm3', 'A1', 'A2', 'A3', 'a', 'b', 'l10', 'l20', 'E1', 'E2', 'c1', 'c2', 'CD', 'r0', 'mu',
    'omega', 'omega_earth', 'rho1', 'rho2', 'rho3', 'I1_roll', 'I1_pitch', 'I1_yaw', 'I2_roll', 'I2_pitch',
    'I2_yaw',
)
PARAMETER_UNITS = (
    'kg', 'kg', 'kg', 'm^2', 'm^2', 'm^2', 'm', 'm', 'm', 'm', 'N', 'N', 'N s/m', 'N s/m', '1', 'm',
    'm^3/s^2', 'rad/s', 'rad/s', 'kg/m^3', 'kg/m^3', 'kg/m^3', 'kg m^2', 'kg m^2', 'kg m^2', 'kg m^2',
    'kg m^2', 'kg m^2',
)
FAMILIES = ('drag1', 'drag2', 'drag3', 'spring1', 'spring2', 'damper1', 'damper2')


@njit(cache=True, inline="always")
def _solve3(s00, s01, s02, s11, s12, s22, v0, v1, v2):
    """x of S x = v for the symmetric 3x3 S (Cramer's rule)."""
    c00 = s11 * s22 - s12 * s12
    c01 = s02 * s12 - s01 * s22
    c02 = s01 * s12 - s02 * s11
    det = s00 * c00 + s01 * c01 + s02 * c02
    c11 = s00 * s22 - s02 * s02
    c12 = s01 * s02 - s00 * s12
    c22 = s00 * s11 - s01 * s01
    return ((c00 * v0 + c01 * v1 + c02 * v2) / det,
            (c01 * v0 + c11 * v1 + c12 * v2) / det,
            (c02 * v0 + c12 * v1 + c22 * v2) / det)


@njit(cache=True, inline="always")
def _solve2(s00, s01, s11, v0, v1):
    """x of S x = v for the symmetric 2x2 S."""
    det = s00 * s11 - s01 * s01
    return (s11 * v0 - s01 * v1) / det, (s00 * v1 - s01 * v0) / det


@njit(cache=True, inline="always")
def rhs(t, y, p, dydt):
    """State derivative dy/dt of model '3d-exact-gravity' (SI; layout in STATE)."""
    delta_x = y[0]
    delta_y = y[1]
    delta_z = y[2]
    phi = y[3]
    theta = y[4]
    psi = y[5]
    delta_x_dot = y[6]
    delta_y_dot = y[7]
    delta_z_dot = y[8]
    phi_dot = y[9]
    theta_dot = y[10]
    psi_dot = y[11]
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
    I1_roll = p[22]
    I1_pitch = p[23]
    I1_yaw = p[24]
    I2_roll = p[25]
    I2_pitch = p[26]
    I2_yaw = p[27]
    sin_phi, cos_phi = sincos(phi)
    sin_theta, cos_theta = sincos(theta)
    sin_psi, cos_psi = sincos(psi)
    # air drag on the three bodies (3.32-3.34)
    d0 = delta_y + r0
    d1 = -d0*omega + d0*omega_earth + delta_x_dot
    d2 = delta_x*omega - delta_x*omega_earth + delta_y_dot
    d3 = (1/2)*CD
    d4 = A3*d3*rho3*math.sqrt(d1**2 + d2**2 + delta_z_dot**2)
    d5 = b**2
    d6 = cos_phi**2
    d7 = d3*d6*phi_dot
    d8 = d6*phi_dot**2
    d9 = b*sin_theta
    d10 = cos_phi*d9
    d11 = phi_dot*sin_phi
    d12 = cos_theta*d11
    d13 = b*cos_phi*omega*sin_theta - b*d12 - d10*omega_earth - d10*theta_dot
    d14 = cos_phi*cos_theta
    d15 = b*d14
    d16 = d15 + r0
    d17 = -d11*d9 + d15*theta_dot - d16*omega + d16*omega_earth
    d18 = math.sqrt(d13**2 + d17**2 + d5*d8)
    d19 = A1*d18*rho1
    d20 = a**2
    d21 = a*sin_theta
    d22 = cos_phi*d21
    d23 = a*d12 - d22*omega + d22*omega_earth + d22*theta_dot
    d24 = a*d14
    d25 = -d24 + r0
    d26 = a*phi_dot*sin_phi*sin_theta - d24*theta_dot - d25*omega + d25*omega_earth
    d27 = math.sqrt(d20*d8 + d23**2 + d26**2)
    d28 = A2*d27*rho2
    d29 = d28*d3*sin_phi
    Q0 = -d1*d4
    Q1 = -d2*d4
    Q2 = -d4*delta_z_dot
    Q3 = (
            (1/2)*A1*CD*b*cos_theta*d13*d18*rho1*sin_phi + (1/2)*A1*CD*b*d17*d18*rho1*sin_phi*
            sin_theta - a*cos_theta*d23*d29 - d19*d5*d7 - d20*d28*d7 - d21*d26*d29)
    Q4 = (
            (1/2)*A1*CD*b*cos_phi*d13*d18*rho1*sin_theta + (1/2)*A2*CD*a*cos_phi*cos_theta*d26*
            d27*rho2 - d15*d17*d19*d3 - d22*d23*d28*d3)
    Q5 = 0
    lambda1 = (
            math.sqrt((b*sin_phi - delta_z)**2 + (b*cos_phi*cos_theta - delta_y)**2 + (b*cos_phi*
            sin_theta - delta_x)**2))
    if lambda1 > l10:  # tether 1 taut: spring1, damper1
        t1_0 = b*cos_phi
        t1_1 = sin_theta*t1_0
        t1_2 = -delta_x + t1_1
        t1_3 = 1/lambda1
        t1_4 = -1 + lambda1/l10
        t1_5 = E1*t1_3*t1_4
        t1_6 = t1_2*t1_5
        t1_7 = cos_theta*t1_0
        t1_8 = b*sin_phi
        t1_9 = phi_dot*t1_8
        t1_10 = delta_x_dot - delta_y*omega + omega*t1_7 + sin_theta*t1_9 - t1_7*theta_dot
        t1_11 = c1*t1_10
        t1_12 = -delta_y + t1_7
        t1_13 = c1*(cos_theta*t1_9 + delta_x*omega + delta_y_dot - omega*t1_1 + t1_1*theta_dot)
        t1_14 = delta_z_dot - phi_dot*t1_0
        t1_15 = t1_5*(-delta_z + t1_8)
        Q0 += -t1_11 + t1_6
        Q1 += t1_12*t1_5 - t1_13
        Q2 += -c1*t1_14 + t1_15
        Q3 += (
                E1*b*cos_theta*sin_phi*t1_12*t1_3*t1_4 + E1*b*sin_phi*sin_theta*t1_2*t1_3*t1_4 +
                b*c1*cos_phi*t1_14 - cos_theta*t1_13*t1_8 - sin_theta*t1_11*t1_8 - t1_0*t1_15)
        Q4 += E1*b*cos_phi*sin_theta*t1_12*t1_3*t1_4 + b*c1*cos_phi*cos_theta*t1_10 - t1_1*t1_13 - t1_6*t1_7
    lambda2 = (
            math.sqrt((-a*sin_phi - delta_z)**2 + (-a*cos_phi*cos_theta - delta_y)**2 + (-a*cos_phi*
            sin_theta - delta_x)**2))
    if lambda2 > l20:  # tether 2 taut: spring2, damper2
        t2_0 = a*cos_phi
        t2_1 = sin_theta*t2_0
        t2_2 = E2*(-1 + lambda2/l20)/lambda2
        t2_3 = t2_2*(-delta_x - t2_1)
        t2_4 = cos_theta*t2_0
        t2_5 = a*sin_phi
        t2_6 = phi_dot*t2_5
        t2_7 = c2*(a*cos_phi*cos_theta*theta_dot + delta_x_dot - delta_y*omega - omega*t2_4 - sin_theta*t2_6)
        t2_8 = t2_2*(-delta_y - t2_4)
        t2_9 = c2*(-cos_theta*t2_6 + delta_x*omega + delta_y_dot + omega*t2_1 - t2_1*theta_dot)
        t2_10 = c2*(delta_z_dot + phi_dot*t2_0)
        t2_11 = t2_2*(-delta_z - t2_5)
        t2_12 = cos_theta*t2_5
        t2_13 = sin_theta*t2_5
        Q0 += t2_3 - t2_7
        Q1 += t2_8 - t2_9
        Q2 += -t2_10 + t2_11
        Q3 += -t2_0*t2_10 + t2_0*t2_11 - t2_12*t2_8 + t2_12*t2_9 - t2_13*t2_3 + t2_13*t2_7
        Q4 += -t2_1*t2_8 + t2_1*t2_9 + t2_3*t2_4 - t2_4*t2_7
    # M q'' + f(q, q') = Q (Lagrange, 3.26-3.31 in 3-D)
    dydt[0] = delta_x_dot
    dydt[1] = delta_y_dot
    dydt[2] = delta_z_dot
    dydt[3] = phi_dot
    dydt[4] = theta_dot
    dydt[5] = psi_dot
    a0 = 1/m3
    a1 = 2*omega
    a2 = a1*m3
    a3 = 2/r0
    a4 = r0**(-2)
    a5 = math.expm1(-1.5*math.log1p(a3*delta_y + a4*delta_x**2 + a4*delta_y**2 + a4*delta_z**2))
    a6 = omega**2
    a7 = a6*m3
    a8 = a5*a7
    a9 = a7*delta_z
    a10 = cos_phi*psi_dot
    a11 = a10*theta_dot
    a12 = cos_psi*sin_psi
    a13 = 2*phi_dot
    a14 = a12*a13*psi_dot
    a15 = I1_yaw*sin_phi
    a16 = a15*cos_phi
    a17 = a1*theta_dot
    a18 = I2_yaw*sin_phi
    a19 = a18*cos_phi
    a20 = theta_dot**2
    a21 = cos_psi**2
    a22 = a10*omega
    a23 = a21*a22
    a24 = sin_psi**2
    a25 = a11*a24
    a26 = a11*a21
    a27 = a22*a24
    a28 = cos_phi*sin_phi
    a29 = a28*a6
    a30 = I1_pitch*a21
    a31 = a20*a28
    a32 = I1_roll*a24
    a33 = I2_pitch*a21
    a34 = I2_roll*a24
    a35 = a**2
    a36 = a35*m2
    a37 = a29*a36
    a38 = b**2
    a39 = a38*m1
    a40 = a29*a39
    a41 = phi_dot**2
    a42 = cos_theta**2
    a43 = a28*a42
    a44 = a36*a43
    a45 = sin_theta**2
    a46 = a28*a41
    a47 = a31*a45
    a48 = a39*a43
    a49 = cos_theta*sin_phi
    a50 = a*a49
    a51 = cos_phi*cos_theta
    a52 = a*a51
    a53 = sin_phi**2
    a54 = a35*a53
    a55 = cos_phi**2
    a56 = a35*a55
    a57 = a42*a56
    a58 = a45*a56
    a59 = math.expm1(-1.5*math.log1p(-a3*a52 + a4*a54 + a4*a57 + a4*a58))
    a60 = a59*a6*m2*r0
    a61 = a51*b
    a62 = a38*a53
    a63 = a38*a55
    a64 = a42*a63
    a65 = a45*a63
    a66 = math.expm1(-1.5*math.log1p(a3*a61 + a4*a62 + a4*a64 + a4*a65))
    a67 = r0**3
    a68 = a49*b
    a69 = 2*r0
    a70 = 2*a28
    a71 = a38*a70
    a72 = a42*a71
    a73 = a45*a71
    a74 = 2*a38*cos_phi*sin_phi - a68*a69 - a72 - a73
    a75 = r0**(-5)
    a76 = a4*(a61*a69 + a62 + a64 + a65)
    a77 = a76 + 1
    a78 = 1/a77
    a79 = a75*a78
    a80 = math.expm1(-1.5*math.log1p(a76))
    a81 = -3/2*a80 - 3/2
    a82 = a81*(I1_pitch + I1_roll + I1_yaw)
    a83 = a80 + 1
    a84 = a77**(-2)
    a85 = b*sin_phi
    a86 = a53*b
    a87 = a55*b
    a88 = a61 + r0
    a89 = I1_yaw*(a45*a87 + a51*a88 + a86)
    a90 = a89*sin_phi
    a91 = cos_phi*cos_psi
    a92 = a85*a91
    a93 = cos_psi*sin_theta
    a94 = a93*sin_phi - cos_theta*sin_psi
    a95 = -a94
    a96 = cos_phi*sin_theta
    a97 = a96*b
    a98 = sin_psi*sin_theta
    a99 = cos_psi*cos_theta
    a100 = a98 + a99*sin_phi
    a101 = -a100
    a102 = a101*a88 + a92 + a95*a97
    a103 = I1_pitch*a102
    a104 = cos_phi*sin_psi
    a105 = a98*sin_phi + a99
    a106 = -a93 + cos_theta*sin_phi*sin_psi
    a107 = -a104*a85 + a105*a97 + a106*a88
    a108 = I1_roll*a107
    a109 = 3*a103*a91 - 3*a104*a108 + 3*a90
    a110 = a89*cos_phi
    a111 = a110*sin_theta
    a112 = I1_roll*a105
    a113 = I1_pitch*a95
    a114 = 3*a102*a113 + 3*a107*a112 + 3*a111
    a115 = I1_roll*a106
    a116 = I1_pitch*a101
    a117 = a102*a116 + a107*a115 + a51*a89
    a118 = 3*a88
    a119 = a109*a85 + a114*a97 + a117*a118
    a120 = a119*a84
    a121 = a120*a83
    a122 = r0**(-7)
    a123 = a122*a74
    a124 = a85*sin_theta
    a125 = 3*a117
    a126 = -a43*b - a45*a70*b - a49*a88 + 2*b*cos_phi*sin_phi
    a127 = cos_psi*sin_phi
    a128 = a87*sin_psi
    a129 = cos_theta*sin_psi
    a130 = a88*cos_phi
    a131 = -a105*a124 - a106*a68 + a128*a45 - a128 + a129*a130 + a86*sin_psi
    a132 = I1_roll*a104
    a133 = -a101*a68 - a124*a95 - a130*a99 - a45*a87*cos_psi + a55*b*cos_psi - a86*cos_psi
    a134 = I1_pitch*a91
    a135 = 3*a85
    a136 = I1_yaw*a126
    a137 = a108*cos_phi
    a138 = a103*cos_phi
    a139 = 3*a97
    a140 = a79*a83
    a141 = a35*a70
    a142 = a141*a42
    a143 = a141*a45
    a144 = 2*a*cos_theta*r0*sin_phi - a142 - a143 + 2*a35*cos_phi*sin_phi
    a145 = a4*(-a52*a69 + a54 + a57 + a58)
    a146 = a145 + 1
    a147 = 1/a146
    a148 = a147*a75
    a149 = math.expm1(-1.5*math.log1p(a145))
    a150 = -3/2*a149 - 3/2
    a151 = a150*(I2_pitch + I2_roll + I2_yaw)
    a152 = a149 + 1
    a153 = a*sin_phi
    a154 = a*a53
    a155 = a*a55
    a156 = -a52 + r0
    a157 = I2_yaw*(-a154 - a155*a45 + a156*cos_phi*cos_theta)
    a158 = a157*sin_phi
    a159 = a153*cos_phi
    a160 = a*a96
    a161 = -a105*a160 + a106*a156 + a159*sin_psi
    a162 = I2_roll*a161
    a163 = a162*sin_psi
    a164 = a159*cos_psi
    a165 = I2_pitch*(a101*a156 - a160*a95 - a164)
    a166 = 3*a158 - 3*a163*cos_phi + 3*a165*a91
    a167 = a157*cos_phi
    a168 = a167*sin_theta
    a169 = a105*a162 + a165*a95 + a168
    a170 = 3*a160
    a171 = a101*a165 + a106*a162 + a157*a51
    a172 = (-a153*a166 + 3*a156*a171 - a169*a170)/a146**2
    a173 = a152*a172
    a174 = a122*a144
    a175 = a150*a172
    a176 = 2*a159
    a177 = -a156*a49 + a159*a42 + a176*a45 - a176
    a178 = a155*sin_psi
    a179 = a156*cos_phi
    a180 = a153*sin_theta
    a181 = I2_roll*(a105*a180 + a106*a50 + a129*a179 - a154*sin_psi - a178*a45 + a178)
    a182 = a155*cos_psi
    a183 = I2_pitch*(a101*a50 + a154*cos_psi - a179*a99 + a180*a95 + a182*a45 - a182)
    a184 = 3*a153
    a185 = I2_yaw*a177
    a186 = a162*cos_phi
    a187 = a165*cos_phi
    a188 = a148*a152
    a189 = a10*phi_dot
    a190 = a1*phi_dot
    a191 = a13*theta_dot
    a192 = a41*sin_psi
    a193 = a127*a192
    a194 = a189*a24
    a195 = a189*a21
    a196 = a190*a28
    a197 = phi_dot*theta_dot
    a198 = a197*a70
    a199 = a12*a55
    a200 = I1_pitch*a199
    a201 = a1*psi_dot
    a202 = 2*psi_dot*theta_dot
    a203 = I1_roll*a199
    a204 = I2_pitch*a199
    a205 = I2_roll*a199
    a206 = a197*m2
    a207 = a196*a45
    a208 = a197*m1
    a209 = r0**(-4)
    a210 = 2*a97
    a211 = r0**(-6)
    a212 = cos_theta*sin_theta
    a213 = a212*a87 - a88*a96
    a214 = a61*a95 + a88*a94
    a215 = -a105
    a216 = a105*a61 + a215*a88
    a217 = I1_yaw*a213
    a218 = (1/2)*a6
    a219 = a218*a67
    a220 = 2*a160
    a221 = a211*a220
    a222 = -a155*a212 - a156*a96
    a223 = I2_pitch*(a156*a94 - a52*a95)
    a224 = I2_roll*(-a105*a52 + a156*a215)
    a225 = I2_yaw*a222
    a226 = cos_phi*phi_dot
    a227 = a226*omega
    a228 = a192*cos_psi
    a229 = a226*theta_dot
    a230 = a227*a24
    a231 = a21*a227
    a232 = a100*a88 - a92 + a94*a97
    a233 = a218*a4
    a234 = I2_roll*(a100*a156 - a160*a94 + a164)
    a235 = I2_pitch*a161
    dydt[6] = a0*(Q0 + a2*delta_y_dot - a8*delta_x)
    dydt[7] = a0*(Q1 - a2*delta_x_dot - a8*delta_y - a8*r0)
    dydt[8] = a0*(Q2 - a5*a9 - a9)
    R3 = (
            -I1_pitch*a14 + 2*I1_pitch*a21*cos_phi*omega*sin_phi*theta_dot + I1_pitch*a21*cos_phi*
            psi_dot*theta_dot - I1_pitch*a23 + I1_pitch*a24*cos_phi*omega*psi_dot - I1_pitch*a25 +
            I1_roll*a21*cos_phi*omega*psi_dot + 2*I1_roll*a24*cos_phi*omega*sin_phi*theta_dot +
            I1_roll*a24*cos_phi*psi_dot*theta_dot - I1_roll*a26 - I1_roll*a27 + 2*I1_roll*cos_psi*
            phi_dot*psi_dot*sin_psi - I1_yaw*a11 + I1_yaw*a20*cos_phi*sin_phi + I1_yaw*a6*cos_phi*
            sin_phi + I1_yaw*cos_phi*omega*psi_dot - I2_pitch*a14 + 2*I2_pitch*a21*cos_phi*omega*
            sin_phi*theta_dot + I2_pitch*a21*cos_phi*psi_dot*theta_dot - I2_pitch*a23 + I2_pitch*a24*
            cos_phi*omega*psi_dot - I2_pitch*a25 + I2_roll*a21*cos_phi*omega*psi_dot + 2*I2_roll*
            a24*cos_phi*omega*sin_phi*theta_dot + I2_roll*a24*cos_phi*psi_dot*theta_dot - I2_roll*
            a26 - I2_roll*a27 + 2*I2_roll*cos_psi*phi_dot*psi_dot*sin_psi - I2_yaw*a11 + I2_yaw*a20*
            cos_phi*sin_phi + I2_yaw*a6*cos_phi*sin_phi + I2_yaw*cos_phi*omega*psi_dot + Q3 - a16*a17
            - a17*a19 - a20*a44 - a20*a48 - a29*a30 - a29*a32 - a29*a33 - a29*a34 - a30*a31 - a31*
            a32 - a31*a33 - a31*a34 + a35*a41*cos_phi*m2*sin_phi + a35*a42*a59*a6*cos_phi*m2*
            sin_phi + 2*a35*a42*cos_phi*m2*omega*sin_phi*theta_dot + a35*a45*a59*a6*cos_phi*m2*
            sin_phi + 2*a35*a45*cos_phi*m2*omega*sin_phi*theta_dot - a36*a45*a46 - a36*a47 - a37*
            a59 - a37 + a38*a41*cos_phi*m1*sin_phi + a38*a42*a6*a66*cos_phi*m1*sin_phi + 2*a38*
            a42*cos_phi*m1*omega*sin_phi*theta_dot + a38*a45*a6*a66*cos_phi*m1*sin_phi + 2*a38*
            a45*cos_phi*m1*omega*sin_phi*theta_dot - a39*a45*a46 - a39*a47 - a40*a66 - a40 - a41*
            a44 - a41*a48 - a50*a60 + a6*a66*b*cos_theta*m1*r0*sin_phi + (1/2)*a6*a67*(-a120*
            a123*a81 + a121*a123 - a140*(a109*b*cos_phi - a114*a124 + a118*(a115*a131 + a116*a133 +
            a129*a137 + a136*a51 - a138*a99 - a49*a89) - a125*a68 + a135*(-a103*a127 + a108*sin_phi*
            sin_psi + a110 + a126*a15 - a131*a132 + a133*a134) + a139*(a112*a131 + a113*a133 + a136*
            a96 + a137*a98 - a138*a93 - a90*sin_theta)) + a74*a79*a82) + (1/2)*a6*a67*(a144*a148*
            a151 + a173*a174 - a174*a175 - a188*(-a*a166*cos_phi + 3*a*a169*sin_phi*sin_theta + 3*
            a*a171*cos_theta*sin_phi + 3*a156*(a101*a183 + a106*a181 + a129*a186 - a157*a49 + a185*
            a51 - a187*a99) - a170*(a105*a181 - a158*sin_theta + a183*a95 + a185*a96 + a186*a98 -
            a187*a93) - a184*(-a104*a181 - a127*a165 + a163*sin_phi + a167 + a177*a18 + a183*a91))))
    R4 = (
            -I1_pitch*a193 - I1_pitch*a194 + I1_roll*a193 - I1_roll*a195 + I1_yaw*a189 - I2_pitch*a193
            - I2_pitch*a194 + I2_roll*a193 - I2_roll*a195 + I2_yaw*a189 + Q4 + a142*a206 + a143*a206 +
            a16*a190 - a16*a191 - a160*a60 + a189*a30 + a189*a32 + a189*a33 + a189*a34 + a19*a190 -
            a19*a191 - a190*a44 - a190*a48 - a196*a30 - a196*a32 - a196*a33 - a196*a34 + a198*a30 +
            a198*a32 + a198*a33 + a198*a34 - a200*a201 + a200*a202 + a201*a203 - a201*a204 + a201*
            a205 - a202*a203 + a202*a204 - a202*a205 - a207*a36 - a207*a39 + a208*a72 + a208*a73 +
            a219*(a147*a151*a209*a220 + a173*a221 - a175*a221 - a188*(3*a*a171*cos_phi*sin_theta +
            3*a156*(a101*a223 + a106*a224 + a162*a215 + a165*a94 - a168 + a225*a51) - 3*a169*a52 -
            a170*(a105*a224 + a171 + a223*a95 + a225*a96) - a184*(-a104*a224 + a18*a222 + a223*a91)))
            + a219*(2*a119*a211*a81*a84*b*cos_phi*sin_theta - a121*a210*a211 - a140*(a114*a61 +
            a118*(a103*a94 + a108*a215 - a111 + a115*a216 + a116*a214 + a217*a51) - a125*a97 + a135*
            (-a132*a216 + a134*a214 + a15*a213) + a139*(a112*a216 + a113*a214 + a117 + a217*a96)) -
            a209*a210*a78*a82) + a6*a66*a97*m1*r0)
    R5 = (
            I1_pitch*a21*cos_phi*omega*phi_dot - I1_pitch*a230 + I1_pitch*a24*cos_phi*phi_dot*
            theta_dot + I1_pitch*a41*cos_psi*sin_psi + 2*I1_pitch*a55*cos_psi*omega*sin_psi*
            theta_dot + I1_roll*a20*a55*cos_psi*sin_psi + I1_roll*a21*cos_phi*phi_dot*theta_dot -
            I1_roll*a228 - I1_roll*a231 + I1_roll*a24*cos_phi*omega*phi_dot + I1_roll*a55*a6*
            cos_psi*sin_psi - I1_yaw*a227 + I1_yaw*cos_phi*phi_dot*theta_dot + I2_pitch*a21*cos_phi*
            omega*phi_dot - I2_pitch*a230 + I2_pitch*a24*cos_phi*phi_dot*theta_dot + I2_pitch*a41*
            cos_psi*sin_psi + 2*I2_pitch*a55*cos_psi*omega*sin_psi*theta_dot + I2_roll*a20*a55*
            cos_psi*sin_psi + I2_roll*a21*cos_phi*phi_dot*theta_dot - I2_roll*a228 - I2_roll*a231 +
            I2_roll*a24*cos_phi*omega*phi_dot + I2_roll*a55*a6*cos_psi*sin_psi - I2_yaw*a227 +
            I2_yaw*cos_phi*phi_dot*theta_dot + Q5 - a147*a152*a233*(3*a156*(a100*a162 + a101*a235 +
            a106*a165 + a106*a234) - a170*(a105*a165 + a105*a234 + a162*a94 + a235*a95) - a184*
            (I2_pitch*a161*cos_phi*cos_psi - a104*a165 - a104*a234 - a162*a91)) - a17*a203 - a17*a205
            - a20*a200 - a20*a204 - a200*a6 - a204*a6 - a229*a30 - a229*a32 - a229*a33 - a229*a34 -
            a233*a78*a83*(a118*(a100*a108 + a103*a106 + a107*a116 + a115*a232) + a135*(I1_pitch*
            a107*cos_phi*cos_psi - a103*a104 - a108*a91 - a132*a232) + a139*(a103*a105 + a107*a113 +
            a108*a94 + a112*a232)))
    mm0 = sin_psi**2
    mm1 = cos_psi**2
    mm2 = a**2*m2
    mm3 = b**2*m1
    mm4 = sin_phi**2
    mm5 = cos_phi**2
    mm6 = mm1*mm5
    mm7 = mm0*mm5
    mm8 = I1_yaw + I2_yaw
    M33 = I1_pitch*mm0 + I1_roll*mm1 + I2_pitch*mm0 + I2_roll*mm1 + mm2 + mm3
    M34 = cos_phi*cos_psi*sin_psi*(-I1_pitch + I1_roll - I2_pitch + I2_roll)
    M35 = 0
    M44 = (
            I1_pitch*mm6 + I1_roll*mm7 + I1_yaw*mm4 + I2_pitch*mm6 + I2_roll*mm7 + I2_yaw*mm4 + mm2*
            mm5 + mm3*mm5)
    M45 = -mm8*sin_phi
    M55 = mm8
    if I1_yaw + I2_yaw == 0.0:
        dydt[9], dydt[10] = _solve2(M33, M34, M44, R3, R4)
        dydt[11] = 0.0
    else:
        dydt[9], dydt[10], dydt[11] = _solve3(M33, M34, M35, M44, M45, M55, R3, R4, R5)


@njit(cache=True)
def family_forces(y, p, out):
    """out[f, k] = generalized force of family FAMILIES[f] on q_k (N or N m)."""
    delta_x = y[0]
    delta_y = y[1]
    delta_z = y[2]
    phi = y[3]
    theta = y[4]
    delta_x_dot = y[6]
    delta_y_dot = y[7]
    delta_z_dot = y[8]
    phi_dot = y[9]
    theta_dot = y[10]
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
    f0_5 = b*cos_phi*omega*sin_theta - cos_theta*f0_4 - f0_2*omega_earth - f0_2*theta_dot
    f0_6 = cos_theta*f0_1
    f0_7 = f0_6 + r0
    f0_8 = -f0_4*sin_theta + f0_6*theta_dot - f0_7*omega + f0_7*omega_earth
    f0_9 = math.sqrt(f0_0*phi_dot**2 + f0_5**2 + f0_8**2)
    f0_10 = (1/2)*A1*CD*f0_9*rho1
    f0_11 = f0_10*f0_3
    out[0, 3] = cos_theta*f0_11*f0_5 - f0_0*f0_10*phi_dot + f0_11*f0_8*sin_theta
    out[0, 4] = (1/2)*A1*CD*b*cos_phi*f0_5*f0_9*rho1*sin_theta - f0_10*f0_6*f0_8
    # drag2: air drag on the main bus (3.32-3.34)
    f1_0 = a**2*cos_phi**2
    f1_1 = a*cos_phi
    f1_2 = f1_1*sin_theta
    f1_3 = a*sin_phi
    f1_4 = cos_theta*f1_3*phi_dot - f1_2*omega + f1_2*omega_earth + f1_2*theta_dot
    f1_5 = cos_theta*f1_1
    f1_6 = -f1_5 + r0
    f1_7 = a*phi_dot*sin_phi*sin_theta - f1_5*theta_dot - f1_6*omega + f1_6*omega_earth
    f1_8 = (1/2)*A2*CD*rho2*math.sqrt(f1_0*phi_dot**2 + f1_4**2 + f1_7**2)
    f1_9 = f1_3*f1_8
    out[1, 3] = -cos_theta*f1_4*f1_9 - f1_0*f1_8*phi_dot - f1_7*f1_9*sin_theta
    out[1, 4] = -f1_2*f1_4*f1_8 + f1_5*f1_7*f1_8
    # drag3: air drag on the balloon (3.32-3.34)
    f2_0 = delta_y + r0
    f2_1 = delta_x_dot - f2_0*omega + f2_0*omega_earth
    f2_2 = delta_x*omega - delta_x*omega_earth + delta_y_dot
    f2_3 = (1/2)*A3*CD*rho3*math.sqrt(delta_z_dot**2 + f2_1**2 + f2_2**2)
    out[2, 0] = -f2_1*f2_3
    out[2, 1] = -f2_2*f2_3
    out[2, 2] = -delta_z_dot*f2_3
    # spring1: tension of tether 1 (3.35-3.42)
    if lambda1 > l10:
        f3_0 = b*cos_phi
        f3_1 = 1/lambda1
        f3_2 = -1 + lambda1/l10
        f3_3 = E1*f3_1*f3_2
        f3_4 = f3_3*(-delta_x + f3_0*sin_theta)
        f3_5 = cos_theta*f3_0
        f3_6 = -delta_y + f3_5
        f3_7 = f3_3*f3_6
        f3_8 = b*sin_phi
        f3_9 = f3_3*(-delta_z + f3_8)
        out[3, 0] = f3_4
        out[3, 1] = f3_7
        out[3, 2] = f3_9
        out[3, 3] = cos_theta*f3_7*f3_8 - f3_0*f3_9 + f3_4*f3_8*sin_theta
        out[3, 4] = E1*b*cos_phi*f3_1*f3_2*f3_6*sin_theta - f3_4*f3_5
    # spring2: tension of tether 2 (3.36-3.42)
    if lambda2 > l20:
        f4_0 = a*cos_phi
        f4_1 = f4_0*sin_theta
        f4_2 = 1/lambda2
        f4_3 = -1 + lambda2/l20
        f4_4 = E2*f4_2*f4_3
        f4_5 = f4_4*(-delta_x - f4_1)
        f4_6 = cos_theta*f4_0
        f4_7 = f4_4*(-delta_y - f4_6)
        f4_8 = a*sin_phi
        f4_9 = -delta_z - f4_8
        out[4, 0] = f4_5
        out[4, 1] = f4_7
        out[4, 2] = f4_4*f4_9
        out[4, 3] = E2*a*cos_phi*f4_2*f4_3*f4_9 - cos_theta*f4_7*f4_8 - f4_5*f4_8*sin_theta
        out[4, 4] = -f4_1*f4_7 + f4_5*f4_6
    # damper1: damping of tether 1 (relative velocity) (3.43)
    if lambda1 > l10:
        f5_0 = b*cos_phi
        f5_1 = cos_theta*f5_0
        f5_2 = b*sin_phi
        f5_3 = f5_2*phi_dot
        f5_4 = c1*(delta_x_dot - delta_y*omega + f5_1*omega - f5_1*theta_dot + f5_3*sin_theta)
        f5_5 = f5_0*sin_theta
        f5_6 = c1*(cos_theta*f5_3 + delta_x*omega + delta_y_dot - f5_5*omega + f5_5*theta_dot)
        f5_7 = delta_z_dot - f5_0*phi_dot
        out[5, 0] = -f5_4
        out[5, 1] = -f5_6
        out[5, 2] = -c1*f5_7
        out[5, 3] = b*c1*cos_phi*f5_7 - cos_theta*f5_2*f5_6 - f5_2*f5_4*sin_theta
        out[5, 4] = f5_1*f5_4 - f5_5*f5_6
    # damper2: damping of tether 2 (relative velocity) (3.44)
    if lambda2 > l20:
        f6_0 = a*cos_phi
        f6_1 = cos_theta*f6_0
        f6_2 = a*sin_phi
        f6_3 = f6_2*phi_dot
        f6_4 = c2*(a*cos_phi*cos_theta*theta_dot + delta_x_dot - delta_y*omega - f6_1*omega - f6_3*sin_theta)
        f6_5 = f6_0*sin_theta
        f6_6 = -cos_theta*f6_3 + delta_x*omega + delta_y_dot + f6_5*omega - f6_5*theta_dot
        f6_7 = c2*f6_6
        f6_8 = c2*(delta_z_dot + f6_0*phi_dot)
        out[6, 0] = -f6_4
        out[6, 1] = -f6_7
        out[6, 2] = -f6_8
        out[6, 3] = cos_theta*f6_2*f6_7 - f6_0*f6_8 + f6_2*f6_4*sin_theta
        out[6, 4] = a*c2*cos_phi*f6_6*sin_theta - f6_1*f6_4


@njit(cache=True)
def jacobi(y, p):
    """Jacobi integral h = Σ q̇ ∂L/∂q̇ − L plus taut-tether spring energy [J].

    Constant with drag and dampers off; otherwise dh/dt = power of drag and dampers.
    """
    delta_x = y[0]
    delta_y = y[1]
    delta_z = y[2]
    phi = y[3]
    theta = y[4]
    psi = y[5]
    delta_x_dot = y[6]
    delta_y_dot = y[7]
    delta_z_dot = y[8]
    phi_dot = y[9]
    theta_dot = y[10]
    psi_dot = y[11]
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
    I1_roll = p[22]
    I1_pitch = p[23]
    I1_yaw = p[24]
    I2_roll = p[25]
    I2_pitch = p[26]
    I2_yaw = p[27]
    sin_phi, cos_phi = sincos(phi)
    sin_theta, cos_theta = sincos(theta)
    sin_psi, cos_psi = sincos(psi)
    e0 = (1/2)*psi_dot**2
    e1 = (1/2)*m3
    e2 = psi_dot*sin_phi*theta_dot
    e3 = cos_psi*sin_psi
    e4 = I1_roll*cos_phi
    e5 = e3*e4
    e6 = phi_dot*theta_dot
    e7 = I2_roll*cos_phi
    e8 = e3*e6
    e9 = omega**2
    e10 = e9*m3
    e11 = cos_phi*e8
    e12 = (1/2)*phi_dot**2
    e13 = sin_psi**2
    e14 = I1_pitch*e13
    e15 = cos_psi**2
    e16 = e12*e15
    e17 = (1/2)*I1_yaw
    e18 = sin_phi**2
    e19 = e18*e9
    e20 = theta_dot**2
    e21 = e18*e20
    e22 = I2_pitch*e13
    e23 = (1/2)*I2_yaw
    e24 = delta_x**2
    e25 = e1*e9
    e26 = delta_y**2
    e27 = a*e9
    e28 = cos_phi*cos_theta
    e29 = e28*r0
    e30 = b*e9
    e31 = (1/2)*I1_pitch
    e32 = cos_phi**2
    e33 = e32*e9
    e34 = e15*e33
    e35 = e20*e32
    e36 = e15*e35
    e37 = (1/2)*I1_roll
    e38 = e13*e33
    e39 = e13*e35
    e40 = (1/2)*I2_pitch
    e41 = (1/2)*I2_roll
    e42 = e12*e32
    e43 = a**2
    e44 = e43*m2
    e45 = b**2
    e46 = e45*m1
    e47 = cos_theta**2
    e48 = e43*e47
    e49 = e48*m2
    e50 = (1/2)*e33
    e51 = (1/2)*e35
    e52 = sin_theta**2
    e53 = e44*e52
    e54 = e12*e18
    e55 = e45*e47
    e56 = e55*m1
    e57 = e46*e52
    e58 = r0**2
    e59 = 2/r0
    e60 = 1/e58
    e61 = e28*e59
    e62 = e18*e60
    e63 = e32*e60
    e64 = e52*e63
    e65 = b*e61 + e45*e62 + e45*e64 + e55*e63
    e66 = e9*math.expm1(-1.5*math.log1p(e65))
    e67 = -a*e61 + e43*e62 + e43*e64 + e48*e63
    e68 = math.expm1(-1.5*math.log1p(e67))
    e69 = e68*e9
    e70 = e58*e9
    e71 = r0**5
    e72 = r0**4
    e73 = e28*e72
    e74 = 2*e73
    e75 = r0**3
    e76 = e18*e75
    e77 = e45*e76
    e78 = e32*e75
    e79 = e55*e78
    e80 = e52*e78
    e81 = e45*e80
    e82 = 1/(b*e74 + e71 + e77 + e79 + e81)
    e83 = 3*e9
    e84 = e82*e83
    e85 = e3*sin_phi
    e86 = e85*sin_theta
    e87 = cos_theta*e71*e86
    e88 = e84*e87
    e89 = e43*e76
    e90 = e48*e78
    e91 = e43*e80
    e92 = 1/(-a*e74 + e71 + e89 + e90 + e91)
    e93 = e83*e92
    e94 = e87*e93
    e95 = e19*e73
    e96 = 3*e82
    e97 = I1_yaw*e96
    e98 = b*e97
    e99 = 3*I2_yaw
    e100 = e92*e99
    e101 = a*e100
    e102 = e101*e95
    e103 = e30*e96
    e104 = cos_phi*e72
    e105 = e104*e86
    e106 = I1_pitch*e105
    e107 = e103*e106
    e108 = e5*e72*sin_phi
    e109 = e108*sin_theta
    e110 = e103*e109
    e111 = 3*I2_pitch
    e112 = e111*e92
    e113 = e112*e27
    e114 = e105*e113
    e115 = e72*e86
    e116 = 3*e92
    e117 = e116*e27*e7
    e118 = e115*e117
    e119 = cos_theta**3
    e120 = cos_phi**3*e72
    e121 = e119*e120
    e122 = e30*e97
    e123 = e100*e27
    e124 = cos_theta*e120*e52
    e125 = sin_theta**3
    e126 = e103*e125
    e127 = e104*e85
    e128 = e125*e127
    e129 = e125*e72*e85
    e130 = I1_pitch*e15
    e131 = b*e96
    e132 = e131*e95
    e133 = e130*e132
    e134 = I1_roll*e13
    e135 = e132*e134
    e136 = e111*e15
    e137 = a*e92
    e138 = e136*e137
    e139 = e138*e95
    e140 = 3*e13
    e141 = I2_roll*e140
    e142 = e137*e141*e95
    e143 = 2*e71
    e144 = 4*e73
    e145 = 1/(b*e144 + e143 + 2*e77 + 2*e79 + 2*e81)
    e146 = e145*e83
    e147 = e52*e71
    e148 = e146*e147
    e149 = I1_roll*e15
    e150 = e75*sin_phi**4
    e151 = I1_yaw*e45
    e152 = e146*e151
    e153 = I1_yaw*e33
    e154 = 3*e145
    e155 = e47*e71
    e156 = e154*e155
    e157 = 1/(-a*e144 + e143 + 2*e89 + 2*e90 + 2*e91)
    e158 = e157*e83
    e159 = e147*e158
    e160 = I2_roll*e15
    e161 = I2_yaw*e43
    e162 = e158*e161
    e163 = e155*e157
    e164 = e33*e99
    e165 = e119*e19
    e166 = e104*e165
    e167 = e130*e131
    e168 = e165*e72
    e169 = e13*e131*e4
    e170 = e138*e166
    e171 = e137*e7
    e172 = e140*e168*e171
    e173 = e77*e96
    e174 = e153*e173
    e175 = cos_phi**4*e75
    e176 = e175*e52
    e177 = e176*e55
    e178 = e89*e92
    e179 = e164*e178
    e180 = e176*e48
    e181 = e139*e52
    e182 = e142*e52
    e183 = e156*e19
    e184 = cos_theta**4
    e185 = e152*e175
    e186 = sin_theta**4
    e187 = e163*e19
    e188 = e136*e187
    e189 = e141*e187
    e190 = e162*e175
    e191 = I1_pitch*e34
    e192 = e173*e191
    e193 = e192*e47
    e194 = I1_roll*e38
    e195 = e173*e194
    e196 = e195*e47
    e197 = e111*e34
    e198 = e178*e197
    e199 = e198*e47
    e200 = I2_roll*e89
    e201 = e200*e38
    e202 = e116*e201
    e203 = e202*e47
    e204 = e154*e77
    e205 = e191*e204
    e206 = e194*e204
    e207 = e157*e89
    e208 = e197*e207
    e209 = 3*e157
    e210 = e201*e209
    e211 = e66*e87*e96
    e212 = e69*e87
    e213 = e66*e98
    e214 = e18*e73
    e215 = e131*e66
    e216 = e111*e137*e69
    e217 = e105*e216
    e218 = 3*e171*e69
    e219 = e115*e218
    e220 = e101*e69
    e221 = e214*e66
    e222 = e167*e221
    e223 = e131*e134*e221
    e224 = e47*e66
    e225 = e131*e224
    e226 = e154*e66
    e227 = e147*e226
    e228 = e151*e226
    e229 = e156*e66
    e230 = e209*e69
    e231 = e147*e230
    e232 = e161*e230
    e233 = e32*e69
    e234 = e119*e18*e66
    e235 = e32*e77
    e236 = e66*e97
    e237 = e235*e236
    e238 = e233*e47
    e239 = e100*e89
    e240 = e233*e52
    e241 = e18*e229
    e242 = e175*e228
    e243 = e175*e232
    e244 = e173*e32
    e245 = e130*e244
    e246 = e224*e245
    e247 = e52*e66
    e248 = e134*e244
    e249 = e224*e248
    e250 = e136*e233
    e251 = e178*e250
    e252 = e251*e47
    e253 = e141*e178
    e254 = e238*e253
    e255 = e226*e235
    e256 = e130*e255
    e257 = e134*e255
    e258 = e207*e250
    e259 = e13*e200*e230*e32
    h = (
            -I1_pitch*e11 + I1_pitch*e126*e127 + I1_pitch*e128*e215 + I1_pitch*e211 + I1_pitch*e88 +
            I1_roll*e16 - I1_roll*e211 - I1_roll*e88 + I1_yaw*e0 + I1_yaw*e177*e84 - I1_yaw*e2 +
            I1_yaw*e229*e32 - I2_pitch*e11 + I2_pitch*e94 - I2_roll*e116*e212 + I2_roll*e16 - I2_roll*
            e94 + I2_yaw*e0 + I2_yaw*e180*e93 - I2_yaw*e2 + delta_x_dot**2*e1 - delta_y*e10*r0 +
            delta_y_dot**2*e1 + delta_z_dot**2*e1 - e10*e58*math.expm1(-0.5*math.log1p(delta_y*e59 +
            delta_z**2*e60 + e24*e60 + e26*e60)) + e100*e180*e69 - e102*e68 - e102 + e104*e167*e234 -
            e106*e215 + e106*e225 + e107*e47 - e107 - e108*e125*e215 - e108*e126 + e109*e215 - e109*
            e225 - e110*e47 + e110 + e112*e212 - e113*e128 - e114*e47 + e114 + e117*e129 + e118*e47 -
            e118 + e12*e14 + e12*e22 + e121*e122 - e121*e123 + e121*e213 - e121*e220 + e122*e124 -
            e123*e124 + e124*e213 - e124*e220 - e128*e216 + e129*e218 + e130*e183 + e130*e241 + e133*
            e52 - e133 + e134*e183 + e134*e241 + e135*e52 - e135 + e139*e68 + e139 + e14*e148 + e14*
            e227 + e142*e68 + e142 + e148*e149 + e149*e227 + e150*e152 + e150*e162 + e150*e228 + e150*
            e232 + e153*e156 + e159*e160 + e159*e22 + e160*e231 + e163*e164 + e163*e233*e99 + e166*
            e167 + e168*e169 + e169*e234*e72 - e17*e19 + e17*e21 - e17*e66 - e170*e68 - e170 - e172*
            e68 - e172 + e174*e47 + e174*e52 + e177*e236 + e179*e47 + e179*e52 - e181*e68 - e181 -
            e182*e68 - e182 + e184*e185 + e184*e190 + e184*e205 + e184*e206 + e184*e208 + e184*e210 +
            e184*e242 + e184*e243 + e184*e256 + e184*e257 + e184*e258 + e184*e259 + e185*e186 + e186*
            e190 + e186*e205 + e186*e206 + e186*e208 + e186*e210 + e186*e242 + e186*e243 + e186*e256 +
            e186*e257 + e186*e258 + e186*e259 + e188*e68 + e188 + e189*e68 + e189 - e19*e23 - e192*e52
            + e193*e52 - e193 - e195*e52 + e196*e52 - e196 - e198*e52 + e199*e52 - e199 - e202*e52 +
            e203*e52 - e203 + e205 + e206 + e208 + e21*e23 + e210 + e213*e214 - e217*e47 + e217 + e219*
            e47 - e219 + e22*e231 + e222*e52 - e222 + e223*e52 - e223 - e23*e69 + e237*e47 + e237*e52 +
            e238*e239 + e239*e240 - e24*e25 - e240*e253 - e245*e247 + e246*e52 - e246 - e247*e248 +
            e249*e52 - e249 - e25*e26 - e251*e52 + e252*e52 - e252 + e254*e52 - e254 + e256 + e257 +
            e258 + e259 + e27*e29*m2 - e29*e30*m1 - e31*e34 + e31*e36 - e31*e66 - e34*e40 + e36*e40
            - e37*e38 + e37*e39 - e37*e66 - e38*e41 + e39*e41 - e40*e69 - e41*e69 + e42*e44 + e42*
            e46 - e49*e50 + e49*e51 + e49*e54 + e5*e6 - e50*e53 - e50*e56 - e50*e57 + e51*e53 + e51*
            e56 + e51*e57 + e53*e54 + e54*e56 + e54*e57 + e7*e8 - e70*m1*math.expm1(-0.5*
            math.log1p(e65)) - e70*m2*math.expm1(-0.5*math.log1p(e67)) + e95*e98)
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

    Positions (docs/three-d.md).
    """
    delta_x = y[0]
    delta_y = y[1]
    delta_z = y[2]
    phi = y[3]
    theta = y[4]
    a = p[6]
    b = p[7]
    r0 = p[15]
    sin_phi, cos_phi = sincos(phi)
    sin_theta, cos_theta = sincos(theta)
    return (
            math.sqrt((b*cos_phi*sin_theta)**2 + (b*cos_phi*cos_theta + r0)**2 + (b*sin_phi)**2),
            math.sqrt((-a*cos_phi*sin_theta)**2 + (-a*cos_phi*cos_theta + r0)**2 + (-a*sin_phi)**2),
            math.sqrt((delta_x)**2 + (delta_y + r0)**2 + (delta_z)**2))
