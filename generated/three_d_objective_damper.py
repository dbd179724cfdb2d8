"""GENERATED FILE - DO NOT EDIT.

Model '3d-objective-damper': 3-D thesis model with Kelvin-Voigt tether dampers (damping of the stretch rate
only).
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

MODEL = '3d-objective-damper'
DESCRIPTION = '3-D thesis model with Kelvin-Voigt tether dampers (damping of the stretch rate only)'
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
    """State derivative dy/dt of model '3d-objective-damper' (SI; layout in STATE)."""
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
        t1_5 = E1*t1_4
        t1_6 = t1_3*t1_5
        t1_7 = t1_2*t1_6
        t1_8 = b*sin_phi
        t1_9 = cos_theta*t1_0
        t1_10 = phi_dot*t1_3
        t1_11 = b**2
        t1_12 = cos_phi*sin_phi*t1_10*t1_11
        t1_13 = (
                max(-t1_5, c1*(b*cos_phi*delta_y*sin_theta*t1_3*theta_dot + b*cos_theta*delta_y*
                phi_dot*sin_phi*t1_3 + b*delta_x*phi_dot*sin_phi*sin_theta*t1_3 + cos_phi*phi_dot*
                sin_phi*t1_11*t1_3 - cos_theta**2*t1_12 + delta_x*delta_x_dot*t1_3 - delta_x*t1_3*
                t1_9*theta_dot - delta_x_dot*t1_1*t1_3 + delta_y*delta_y_dot*t1_3 - delta_y_dot*t1_3*
                t1_9 + delta_z*delta_z_dot*t1_3 - delta_z*t1_0*t1_10 - delta_z_dot*t1_3*t1_8 -
                sin_theta**2*t1_12)))
        t1_14 = t1_13*t1_3
        t1_15 = t1_14*t1_2
        t1_16 = -delta_y + t1_9
        t1_17 = t1_16*t1_6
        t1_18 = t1_14*t1_16
        t1_19 = -delta_z + t1_8
        t1_20 = t1_19*t1_6
        t1_21 = t1_14*t1_19
        t1_22 = cos_theta*t1_8
        t1_23 = sin_theta*t1_8
        Q0 += t1_15 + t1_7
        Q1 += t1_17 + t1_18
        Q2 += t1_20 + t1_21
        Q3 += -t1_0*t1_20 - t1_0*t1_21 + t1_15*t1_23 + t1_17*t1_22 + t1_18*t1_22 + t1_23*t1_7
        Q4 += (
                E1*b*cos_phi*sin_theta*t1_16*t1_3*t1_4 + b*cos_phi*sin_theta*t1_13*t1_16*t1_3 -
                t1_15*t1_9 - t1_7*t1_9)
    lambda2 = (
            math.sqrt((-a*sin_phi - delta_z)**2 + (-a*cos_phi*cos_theta - delta_y)**2 + (-a*cos_phi*
            sin_theta - delta_x)**2))
    if lambda2 > l20:  # tether 2 taut: spring2, damper2
        t2_0 = a*cos_phi
        t2_1 = sin_theta*t2_0
        t2_2 = -delta_x - t2_1
        t2_3 = 1/lambda2
        t2_4 = -1 + lambda2/l20
        t2_5 = E2*t2_4
        t2_6 = t2_3*t2_5
        t2_7 = t2_2*t2_6
        t2_8 = delta_x_dot*t2_3
        t2_9 = delta_y_dot*t2_3
        t2_10 = delta_z_dot*t2_3
        t2_11 = a*sin_phi
        t2_12 = cos_theta*t2_0
        t2_13 = phi_dot*t2_3
        t2_14 = t2_3*theta_dot
        t2_15 = a**2*cos_phi*sin_phi*t2_13
        t2_16 = t2_11*t2_13
        t2_17 = (
                max(-t2_5, c2*(-cos_theta**2*t2_15 - cos_theta*delta_y*t2_16 - delta_x*sin_theta*t2_16
                + delta_x*t2_12*t2_14 + delta_x*t2_8 - delta_y*t2_1*t2_14 + delta_y*t2_9 + delta_z*
                t2_0*t2_13 + delta_z*t2_10 - sin_theta**2*t2_15 + t2_1*t2_8 + t2_10*t2_11 + t2_12*t2_9
                + t2_15)))
        t2_18 = t2_17*t2_3
        t2_19 = t2_18*t2_2
        t2_20 = -delta_y - t2_12
        t2_21 = t2_20*t2_6
        t2_22 = t2_18*t2_20
        t2_23 = -delta_z - t2_11
        t2_24 = cos_theta*t2_11
        t2_25 = sin_theta*t2_11
        Q0 += t2_19 + t2_7
        Q1 += t2_21 + t2_22
        Q2 += t2_18*t2_23 + t2_23*t2_6
        Q3 += (
                E2*a*cos_phi*t2_23*t2_3*t2_4 + a*cos_phi*t2_17*t2_23*t2_3 - t2_19*t2_25 - t2_21*
                t2_24 - t2_22*t2_24 - t2_25*t2_7)
        Q4 += -t2_1*t2_21 - t2_1*t2_22 + t2_12*t2_19 + t2_12*t2_7
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
    a3 = 1/r0
    a4 = omega**2
    a5 = a4*m3
    a6 = 3*delta_y
    a7 = a5*a6
    a8 = a3*a5
    a9 = (3/2)*a8
    a10 = a5*delta_z
    a11 = I1_yaw*cos_phi
    a12 = psi_dot*theta_dot
    a13 = I2_yaw*cos_phi
    a14 = cos_psi*sin_psi
    a15 = I1_pitch*a14
    a16 = phi_dot*psi_dot
    a17 = 2*a16
    a18 = a11*sin_phi
    a19 = a1*theta_dot
    a20 = a13*sin_phi
    a21 = theta_dot**2
    a22 = I1_pitch*cos_phi
    a23 = cos_psi**2
    a24 = omega*psi_dot
    a25 = a23*a24
    a26 = sin_psi**2
    a27 = a12*a26
    a28 = a12*a23
    a29 = I1_roll*cos_phi
    a30 = a24*a26
    a31 = I2_pitch*cos_phi
    a32 = I2_roll*cos_phi
    a33 = a4*sin_phi
    a34 = a22*a23
    a35 = a33*a34
    a36 = a21*sin_phi
    a37 = a26*a29
    a38 = a33*a37
    a39 = a23*a31
    a40 = a33*a39
    a41 = a26*a32
    a42 = a33*a41
    a43 = a**2
    a44 = a43*m2
    a45 = cos_phi*sin_phi
    a46 = a4*a45
    a47 = a44*a46
    a48 = b**2
    a49 = a48*m1
    a50 = a46*a49
    a51 = cos_theta**2
    a52 = phi_dot**2
    a53 = a14*a22
    a54 = 3*a4
    a55 = cos_theta*sin_theta
    a56 = a54*a55
    a57 = I2_pitch*a
    a58 = a3*cos_theta
    a59 = (3/2)*a33*a58
    a60 = a*a59
    a61 = a45*a52
    a62 = a44*a61
    a63 = a21*a45
    a64 = a44*a63
    a65 = sin_theta**2
    a66 = a49*a61
    a67 = a49*a63
    a68 = 3*a51
    a69 = sin_phi**3
    a70 = a58*a69
    a71 = I2_yaw*a54
    a72 = a*a71
    a73 = I1_yaw*a33
    a74 = cos_phi**2
    a75 = a58*a74
    a76 = 6*b
    a77 = a75*a76
    a78 = a**3
    a79 = b**3
    a80 = a79*m1
    a81 = (3/2)*a4
    a82 = sin_phi**2
    a83 = a54*a82
    a84 = a3*b
    a85 = a84*sin_theta
    a86 = a83*a85
    a87 = a14*a74
    a88 = I1_roll*a4
    a89 = a87*a88
    a90 = a*a3
    a91 = a90*sin_theta
    a92 = a4*a87
    a93 = I2_pitch*a92
    a94 = I2_roll*a54
    a95 = a14*a82
    a96 = I1_pitch*cos_theta
    a97 = a54*a96
    a98 = a69*a84
    a99 = a23*a98
    a100 = 3*a88
    a101 = a26*a70
    a102 = cos_theta**3
    a103 = a102*a74
    a104 = a78*m2
    a105 = 3*a33
    a106 = sin_theta**3
    a107 = a106*a84
    a108 = I1_pitch*a92
    a109 = a33*a84*a96
    a110 = (15/2)*a26
    a111 = (15/2)*a23
    a112 = a33*a58
    a113 = a23*a57
    a114 = a33*a75
    a115 = a106*a90
    a116 = I2_pitch*a54
    a117 = a116*a82
    a118 = I2_roll*a92
    a119 = 6*a
    a120 = I2_roll*a26
    a121 = (9/2)*a102
    a122 = a3*a80
    a123 = a103*a33
    a124 = a15*a4
    a125 = 12*a51
    a126 = a125*a85
    a127 = a125*a91
    a128 = a4*a51
    a129 = 9*a123
    a130 = a1*phi_dot
    a131 = phi_dot*theta_dot
    a132 = 2*a131
    a133 = a14*a52
    a134 = I1_roll*a133
    a135 = I2_roll*a133
    a136 = a16*a26
    a137 = I1_pitch*a133
    a138 = a16*a23
    a139 = I2_pitch*a133
    a140 = a130*sin_phi
    a141 = a131*a34
    a142 = 2*sin_phi
    a143 = I1_pitch*a87
    a144 = a1*psi_dot
    a145 = 2*a12
    a146 = a131*a37
    a147 = I1_roll*a87
    a148 = a131*a39
    a149 = I2_pitch*a87
    a150 = a131*a41
    a151 = I2_roll*a87
    a152 = a26*sin_theta
    a153 = a23*a55
    a154 = I1_yaw*a54
    a155 = a55*a74
    a156 = a152*cos_theta
    a157 = a81*sin_theta
    a158 = a157*a84
    a159 = a33*a68
    a160 = a15*a65
    a161 = a14*a159
    a162 = a14*a65
    a163 = a105*a162
    a164 = a31*a90
    a165 = a157*a90
    a166 = a130*a45
    a167 = a166*a44
    a168 = a132*a45
    a169 = a168*a44
    a170 = a166*a49
    a171 = a168*a49
    a172 = a23*sin_theta
    a173 = a156*a82
    a174 = a155*a54
    a175 = a83*a91
    a176 = a58*b
    a177 = a105*a14
    a178 = a31*a58
    a179 = a*a177
    a180 = a32*a58
    a181 = cos_phi**3
    a182 = a181*a3
    a183 = a106*a182
    a184 = a22*a4
    a185 = a29*a4
    a186 = (39/2)*a128
    a187 = a186*a85
    a188 = a106*a4
    a189 = a32*a90
    a190 = a157*a82*cos_phi
    a191 = 12*a102
    a192 = a53*a84
    a193 = a29*a84
    a194 = a193*a33
    a195 = a14*a191
    a196 = a195*a33
    a197 = a183*a81
    a198 = 15*a128
    a199 = a152*a22*a84
    a200 = a172*a198
    a201 = a152*a164
    a202 = 33*a112*a162
    a203 = a202*b
    a204 = a*a202
    a205 = a157*a182*a51
    a206 = a107*a83
    a207 = a115*a83
    a208 = a187*a82
    a209 = a186*a82*a91
    a210 = omega*phi_dot
    a211 = a131*a26
    a212 = a131*a23
    a213 = a210*a26
    a214 = a210*a23
    a215 = a21*a87
    a216 = a105*a96
    a217 = a105*a153
    a218 = a105*a156
    a219 = a68*a82
    a220 = a14*a219
    a221 = a220*a4
    a222 = 3*a85
    a223 = a105*a172
    a224 = 3*a91
    a225 = a4*a82
    a226 = a58*a76
    a227 = 15*a162
    a228 = a176*a227
    a229 = a185*a95
    a230 = a178*a4
    a231 = a119*a230
    a232 = a*a227
    a233 = a4*a95
    a234 = a119*a180
    a235 = 3*a107
    a236 = a105*a107
    a237 = 3*a115
    a238 = a105*a106
    a239 = 9*a102
    a240 = a125*a33
    a241 = a233*a239
    a242 = a162*a82
    a243 = a226*a242
    dydt[6] = a0*(Q0 + a2*delta_y_dot + a3*a7*delta_x)
    dydt[7] = a0*(Q1 - a2*delta_x_dot + a7 + (9/2)*a8*delta_y**2 + a9*delta_x**2 + a9*delta_z**2)
    dydt[8] = a0*(Q2 + a10*a3*a6 - a10)
    R3 = (
            9*I1_pitch*a102*a23*a3*a4*a74*b*sin_phi + 3*I1_pitch*a106*a3*a4*a82*b*cos_psi*
            sin_psi - I1_pitch*a121*a4*a99 + 3*I1_pitch*a23*a3*a4*a65*a69*b*cos_theta + 6*
            I1_pitch*a23*a3*a4*a74*b*cos_theta*sin_phi + 2*I1_pitch*a23*cos_phi*omega*sin_phi*
            theta_dot + I1_pitch*a23*cos_phi*psi_dot*theta_dot + I1_pitch*a26*cos_phi*omega*psi_dot +
            12*I1_pitch*a3*a4*a51*a74*b*cos_psi*sin_psi*sin_theta + 3*I1_pitch*a3*a4*a74*b*
            cos_psi*sin_psi*sin_theta + (3/2)*I1_pitch*a3*a4*b*cos_theta*sin_phi + 9*I1_roll*a102*
            a26*a3*a4*a74*b*sin_phi + 3*I1_roll*a106*a3*a4*a74*b*cos_psi*sin_psi - I1_roll*
            a111*a112*a65*b + I1_roll*a23*cos_phi*omega*psi_dot + 3*I1_roll*a26*a3*a4*a65*a69*
            b*cos_theta + 6*I1_roll*a26*a3*a4*a74*b*cos_theta*sin_phi - I1_roll*a26*a33*a65*a77
            + 2*I1_roll*a26*cos_phi*omega*sin_phi*theta_dot + I1_roll*a26*cos_phi*psi_dot*theta_dot
            + 12*I1_roll*a3*a4*a51*a82*b*cos_psi*sin_psi*sin_theta + 3*I1_roll*a3*a4*a82*b*
            cos_psi*sin_psi*sin_theta + (3/2)*I1_roll*a3*a4*b*cos_theta*sin_phi + 3*I1_roll*a4*
            cos_phi*cos_psi*cos_theta*sin_psi*sin_theta + 2*I1_roll*cos_psi*phi_dot*psi_dot*sin_psi
            + I1_yaw*a21*cos_phi*sin_phi + 9*I1_yaw*a3*a4*a65*a74*b*cos_theta*sin_phi + 3*I1_yaw*
            a3*a4*a69*b*cos_theta + (3/2)*I1_yaw*a3*a4*b*cos_theta*sin_phi + 3*I1_yaw*a4*a51*
            cos_phi*sin_phi + I1_yaw*a4*cos_phi*sin_phi + I1_yaw*cos_phi*omega*psi_dot + (9/2)*
            I2_pitch*a*a102*a23*a3*a4*a69 + 3*I2_pitch*a*a106*a3*a4*a74*cos_psi*sin_psi + 6*
            I2_pitch*a*a23*a3*a4*a65*a74*cos_theta*sin_phi + 3*I2_pitch*a*a23*a3*a4*a69*
            cos_theta + (15/2)*I2_pitch*a*a26*a3*a4*a65*cos_theta*sin_phi + 12*I2_pitch*a*a3*a4*
            a51*a82*cos_psi*sin_psi*sin_theta + 3*I2_pitch*a*a3*a4*a82*cos_psi*sin_psi*sin_theta
            - I2_pitch*a14*a17 + 2*I2_pitch*a23*cos_phi*omega*sin_phi*theta_dot + I2_pitch*a23*
            cos_phi*psi_dot*theta_dot + I2_pitch*a26*cos_phi*omega*psi_dot + (9/2)*I2_roll*a*a102*
            a26*a3*a4*a69 + 3*I2_roll*a*a106*a3*a4*a82*cos_psi*sin_psi + (15/2)*I2_roll*a*a23*
            a3*a4*a65*cos_theta*sin_phi + 6*I2_roll*a*a26*a3*a4*a65*a74*cos_theta*sin_phi + 3*
            I2_roll*a*a26*a3*a4*a69*cos_theta + 12*I2_roll*a*a3*a4*a51*a74*cos_psi*sin_psi*
            sin_theta + 3*I2_roll*a*a3*a4*a74*cos_psi*sin_psi*sin_theta - 12*I2_roll*a128*a91*a95
            + I2_roll*a23*cos_phi*omega*psi_dot + 2*I2_roll*a26*cos_phi*omega*sin_phi*theta_dot +
            I2_roll*a26*cos_phi*psi_dot*theta_dot + 3*I2_roll*a4*cos_phi*cos_psi*cos_theta*sin_psi*
            sin_theta - I2_roll*a60 + 2*I2_roll*cos_psi*phi_dot*psi_dot*sin_psi + (27/2)*I2_yaw*a*
            a102*a3*a4*a74*sin_phi + 6*I2_yaw*a*a3*a4*a74*cos_theta*sin_phi - 9*I2_yaw*a*a33*
            a65*a75 + I2_yaw*a21*cos_phi*sin_phi + 3*I2_yaw*a4*a51*cos_phi*sin_phi + I2_yaw*a4*
            cos_phi*sin_phi - I2_yaw*a60 + I2_yaw*cos_phi*omega*psi_dot + Q3 - a*a101*a65*a94 - a*
            a116*a23*a65*a70 - a100*a101*b - a100*a107*a95 + (9/2)*a102*a3*a4*a74*a78*m2*
            sin_phi - 27/2*a103*a73*a84 - a104*a105*a75 - 3*a107*a108 - a109*a110*a65 - 6*a109*
            a23*a65*a74 - a11*a12 - 6*a113*a114 - a113*a129*a3 - a114*a119*a120 - 9/2*a114*a65*
            a80 - a115*a117*a14 - 3*a115*a118 - a12*a13 - a120*a129*a90 - a121*a26*a88*a98 - 9/2*
            a122*a123 - a124*a126*a82 - a126*a89 - a127*a93 - a14*a31*a56 - a15*a17 - a15*a86 - a18*
            a19 - a19*a20 - a22*a25 - a22*a27 - a25*a31 - a27*a31 - a28*a29 - a28*a32 - a29*a30 +
            (9/2)*a3*a4*a65*a74*a78*cos_theta*m2*sin_phi + (3/2)*a3*a4*a69*a78*cos_theta*m2 +
            3*a3*a4*a74*a79*cos_theta*m1*sin_phi - a30*a32 - a34*a36 - a35*a68 - a35 - a36*a37 -
            a36*a39 - a36*a41 - a38*a68 - a38 - a40*a68 - a40 - a42*a68 - a42 + 2*a43*a51*cos_phi*
            m2*omega*sin_phi*theta_dot + a43*a52*cos_phi*m2*sin_phi + 2*a43*a65*cos_phi*m2*omega*
            sin_phi*theta_dot - a47*a68 - a47 + 2*a48*a51*cos_phi*m1*omega*sin_phi*theta_dot + a48*
            a52*cos_phi*m1*sin_phi + 2*a48*a65*cos_phi*m1*omega*sin_phi*theta_dot - a50*a68 - a50
            - a51*a62 - a51*a64 - a51*a66 - a51*a67 - a53*a56 - a57*a59 - a62*a65 - a64*a65 - a65*
            a66 - a65*a67 - a70*a72 - a70*a80*a81 - a73*a77 - 3*a85*a89 - 3*a91*a93 - a91*a94*a95
            - a97*a99)
    R4 = (
            I1_roll*a161 - I1_roll*a163 - I1_yaw*a181*a187 - I2_pitch*a161 + I2_pitch*a163 + I2_roll*
            a161 - I2_roll*a163 + I2_yaw*a*a182*a186*sin_theta + Q4 - a100*a153 + a100*a173 + a104*
            a190*a3 + a104*a197 + a104*a205 + a105*a160 + a105*a176*a53 - a107*a110*a184 - a107*
            a111*a185 + a11*a158 + a11*a16 + a11*a86 + a110*a164*a188 + a111*a188*a189 - a116*a156 +
            a117*a153 - a122*a190 + a13*a16 - a13*a165 - a13*a175 + a130*a18 + a130*a20 - a132*a18 -
            a132*a20 + a134*sin_phi + a135*sin_phi - a136*a22 - a136*a31 - a137*sin_phi - a138*a29 -
            a138*a32 - a139*sin_phi - a140*a34 - a140*a37 - a140*a39 - a140*a41 + a141*a142 + a142*
            a146 + a142*a148 + a142*a150 - a143*a144 + a143*a145 + a144*a147 - a144*a149 + a144*a151 -
            a145*a147 + a145*a149 - a145*a151 - a15*a159 - a152*a97 - a153*a94 + a154*a155 + a154*
            a183*b + a155*a71 - a157*a164 + a158*a22 + a158*a29 + a16*a34 + a16*a37 + a16*a39 + a16*
            a41 - a164*a196 - a165*a32 - a167*a51 - a167*a65 + a169*a51 + a169*a65 - a170*a51 - a170*
            a65 + a171*a51 + a171*a65 + a172*a82*a97 + a173*a94 - a174*a44 - a174*a49 + a175*a39 +
            a175*a41 - a176*a177*a29 - a178*a179 + a179*a180 - a183*a72 + a189*a196 - a189*a200 +
            a191*a192*a33 + a193*a200 - a194*a195 - a197*a80 + a198*a199 - a198*a201 - a203*a22 +
            a203*a29 + a204*a31 - a204*a32 - a205*a80 + a206*a34 + a206*a37 - a207*a39 - a207*a41 -
            a208*a34 - a208*a37 + a209*a39 + a209*a41 - a34*a86 - a37*a86)
    R5 = (
            -I1_pitch*a215 + I1_roll*a215 + I1_roll*a217 - I1_roll*a218 - I2_pitch*a215 - I2_pitch*a217
            + I2_pitch*a218 + I2_pitch*a221 + I2_roll*a215 + I2_roll*a217 - I2_roll*a218 - I2_roll*a221
            + Q5 + a100*a162 - a105*a199 + a105*a201 - a108 + a11*a131 - a11*a210 - a116*a162 + a118 +
            a124*a219 - a125*a172*a194 + a126*a35 + a126*a38 - a127*a40 - a127*a42 + a13*a131 - a13*
            a210 - a134 - a135 + a137 + a139 - a141 + a143*a19 - a146 - a147*a19 - a148 + a149*a19 - a150
            - a151*a19 + a152*a216 - a160*a54 + a162*a225*a234 + a162*a94 - a164*a238*a26 + a164*
            a241 + a172*a189*a240 - a172*a216 + a180*a232*a4 + a184*a228 + a184*a243 - a185*a228 -
            a185*a243 + a189*a223 - a189*a23*a238 - a189*a241 - a192*a225*a239 - a193*a223 - a199*
            a240 + a201*a240 + a210*a34 + a210*a37 + a210*a39 + a210*a41 + a211*a22 + a211*a31 + a212*
            a29 + a212*a32 - a213*a22 - a213*a31 - a214*a29 - a214*a32 + a22*a236*a26 - a220*a88 +
            a222*a35 + a222*a38 - a224*a40 - a224*a42 - a225*a226*a53 + a226*a229 + a229*a239*a84 +
            a23*a236*a29 - a230*a232 - a231*a242 + a231*a95 - a233*a234 - a235*a35 - a235*a38 + a237*
            a40 + a237*a42 + a89 - a93)
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
    # damper1: damping of tether 1 along its stretch rate (variant (issue 5))
    if lambda1 > l10:
        f5_0 = b*cos_phi
        f5_1 = f5_0*sin_theta
        f5_2 = 1/lambda1
        f5_3 = b*sin_phi
        f5_4 = cos_theta*f5_0
        f5_5 = f5_2*phi_dot
        f5_6 = b**2
        f5_7 = cos_phi*f5_5*f5_6*sin_phi
        f5_8 = (
                max(-E1*(-1 + lambda1/l10), c1*(b*cos_phi*delta_y*f5_2*sin_theta*theta_dot + b*
                cos_theta*delta_y*f5_2*phi_dot*sin_phi + b*delta_x*f5_2*phi_dot*sin_phi*sin_theta +
                cos_phi*f5_2*f5_6*phi_dot*sin_phi - cos_theta**2*f5_7 + delta_x*delta_x_dot*f5_2 -
                delta_x*f5_2*f5_4*theta_dot - delta_x_dot*f5_1*f5_2 + delta_y*delta_y_dot*f5_2 -
                delta_y_dot*f5_2*f5_4 + delta_z*delta_z_dot*f5_2 - delta_z*f5_0*f5_5 - delta_z_dot*
                f5_2*f5_3 - f5_7*sin_theta**2)))
        f5_9 = f5_2*f5_8
        f5_10 = f5_9*(-delta_x + f5_1)
        f5_11 = -delta_y + f5_4
        f5_12 = f5_11*f5_9
        f5_13 = f5_9*(-delta_z + f5_3)
        out[5, 0] = f5_10
        out[5, 1] = f5_12
        out[5, 2] = f5_13
        out[5, 3] = cos_theta*f5_12*f5_3 - f5_0*f5_13 + f5_10*f5_3*sin_theta
        out[5, 4] = b*cos_phi*f5_11*f5_2*f5_8*sin_theta - f5_10*f5_4
    # damper2: damping of tether 2 along its stretch rate (variant (issue 5))
    if lambda2 > l20:
        f6_0 = a*cos_phi
        f6_1 = f6_0*sin_theta
        f6_2 = 1/lambda2
        f6_3 = delta_x_dot*f6_2
        f6_4 = delta_y_dot*f6_2
        f6_5 = delta_z_dot*f6_2
        f6_6 = a*sin_phi
        f6_7 = cos_theta*f6_0
        f6_8 = f6_2*phi_dot
        f6_9 = f6_2*theta_dot
        f6_10 = a**2*cos_phi*f6_8*sin_phi
        f6_11 = f6_6*f6_8
        f6_12 = (
                max(-E2*(-1 + lambda2/l20), c2*(-cos_theta**2*f6_10 - cos_theta*delta_y*f6_11 - delta_x*
                f6_11*sin_theta + delta_x*f6_3 + delta_x*f6_7*f6_9 - delta_y*f6_1*f6_9 + delta_y*f6_4
                + delta_z*f6_0*f6_8 + delta_z*f6_5 + f6_1*f6_3 - f6_10*sin_theta**2 + f6_10 + f6_4*f6_7
                + f6_5*f6_6)))
        f6_13 = f6_12*f6_2
        f6_14 = f6_13*(-delta_x - f6_1)
        f6_15 = f6_13*(-delta_y - f6_7)
        f6_16 = -delta_z - f6_6
        out[6, 0] = f6_14
        out[6, 1] = f6_15
        out[6, 2] = f6_13*f6_16
        out[6, 3] = a*cos_phi*f6_12*f6_16*f6_2 - cos_theta*f6_15*f6_6 - f6_14*f6_6*sin_theta
        out[6, 4] = -f6_1*f6_15 + f6_14*f6_7


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
    e3 = I1_roll*cos_phi
    e4 = cos_psi*sin_psi
    e5 = e3*e4
    e6 = phi_dot*theta_dot
    e7 = I2_roll*cos_phi
    e8 = e4*e6
    e9 = cos_phi*e8
    e10 = (1/2)*phi_dot**2
    e11 = sin_psi**2
    e12 = I1_pitch*e11
    e13 = cos_psi**2
    e14 = e10*e13
    e15 = omega**2
    e16 = sin_phi**2
    e17 = (1/2)*e16
    e18 = e15*e17
    e19 = theta_dot**2
    e20 = e17*e19
    e21 = I2_pitch*e11
    e22 = (3/2)*e15
    e23 = e22*m3
    e24 = delta_z**2*e15
    e25 = 3*cos_theta
    e26 = e15*sin_phi
    e27 = e4*sin_theta
    e28 = e26*e27
    e29 = e25*e28
    e30 = I1_pitch*e13
    e31 = cos_phi**2
    e32 = (1/2)*e31
    e33 = e15*e32
    e34 = e19*e32
    e35 = sin_theta**2
    e36 = e22*e35
    e37 = e11*e33
    e38 = e11*e34
    e39 = e13*e36
    e40 = cos_theta**2
    e41 = e22*e40
    e42 = e31*e41
    e43 = I2_pitch*e13
    e44 = e10*e31
    e45 = a**2*m2
    e46 = b**2*m1
    e47 = 1/r0
    e48 = e23*e47
    e49 = cos_phi*cos_theta
    e50 = b*e47
    e51 = e22*e50
    e52 = cos_theta*e3
    e53 = I1_yaw*e50
    e54 = e22*e47
    e55 = a*e54
    e56 = e49*e55
    e57 = cos_theta*e7
    e58 = e16*e41
    e59 = e11*e58
    e60 = e34*e45
    e61 = e10*e16
    e62 = e45*e61
    e63 = e34*e46
    e64 = e46*e61
    e65 = e15*e53
    e66 = e16*e49
    e67 = 3*e66
    e68 = a*e15*e47
    e69 = I2_yaw*e68
    e70 = 3*e50
    e71 = I1_pitch*cos_phi*e70
    e72 = e5*e70
    e73 = e26*sin_theta
    e74 = I2_pitch*cos_phi*e68
    e75 = 3*sin_phi
    e76 = e27*e75
    e77 = e68*e7
    e78 = cos_phi**3
    e79 = cos_theta**3
    e80 = e78*e79
    e81 = (9/2)*e80
    e82 = e25*e35*e78
    e83 = a**3*m2
    e84 = e54*e66
    e85 = b**3*m1
    e86 = sin_theta**3
    e87 = e26*e86
    e88 = e4*e75*e86
    e89 = e54*e80
    e90 = e15*e50
    e91 = e30*e90
    e92 = e67*e91
    e93 = (15/2)*e35
    e94 = e49*e93
    e95 = e52*e90
    e96 = e13*e93
    e97 = e11*e16
    e98 = 3*e97
    e99 = e95*e98
    e100 = e43*e68
    e101 = e100*e67
    e102 = e57*e68
    e103 = e102*e98
    e104 = 12*e40
    e105 = e104*e50
    e106 = e104*e27*sin_phi
    e107 = cos_theta*e36*e47*e78
    e108 = (9/2)*e79
    e109 = cos_phi*e108*e16
    e110 = e108*e97
    h = (
            -I1_pitch*cos_phi*e105*e28 + I1_pitch*e29 + I1_pitch*e49*e51 - I1_pitch*e9 + I1_roll*e14
            - I1_roll*e29 - I1_roll*e37 + I1_roll*e38 + I1_roll*e39 + I1_roll*e59 + I1_yaw*e0 - I1_yaw*
            e18 - I1_yaw*e2 + I1_yaw*e20 + I1_yaw*e42 + I2_pitch*e29 - I2_pitch*e56 - I2_pitch*e9 +
            I2_roll*e14 - I2_roll*e29 - I2_roll*e37 + I2_roll*e38 + I2_roll*e39 + I2_roll*e59 + I2_yaw*
            e0 - I2_yaw*e18 - I2_yaw*e2 + I2_yaw*e20 + I2_yaw*e42 - I2_yaw*e56 - delta_x**2*delta_y*
            e48 + delta_x_dot**2*e1 - delta_y**3*e48 - delta_y**2*e23 - 3/2*delta_y*e24*e47*m3 +
            delta_y_dot**2*e1 + delta_z_dot**2*e1 + e1*e24 + e10*e12 + e10*e21 + e100*e109 - e101*e35
            + e101 + e102*e96 - e103*e35 + e103 + e105*e5*e73 + e106*e74 - e106*e77 + e107*e83 - e107*
            e85 - e109*e91 - e110*e3*e90 + e110*e77 + e12*e36 - e12*e90*e94 + e18*e45 + e18*e46 +
            e21*e36 + e21*e68*e94 + e22*e49*e53 - e28*e71 - e30*e33 + e30*e34 + e30*e58 - e33*e43 +
            e34*e43 + e35*e60 + e35*e62 + e35*e63 + e35*e64 + e35*e92 + e35*e99 + e4*e71*e87 + e40*
            e60 + e40*e62 + e40*e63 + e40*e64 - e42*e45 - e42*e46 + e43*e58 + e44*e45 + e44*e46 + e5*
            e6 + e51*e52 - e55*e57 + e65*e67 - e65*e81 + e65*e82 - e67*e69 + e69*e81 - e69*e82 + e7*
            e8 + e72*e73 - e72*e87 + e74*e76 - e74*e88 - e76*e77 + e77*e88 + e83*e84 + e83*e89 - e84*
            e85 - e85*e89 - e92 - e95*e96 - e99)
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
