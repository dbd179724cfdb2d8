"""GENERATED FILE - DO NOT EDIT.  Produced by `make derive` from derive/symbols.py.

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

Y_DELTA_X = 0
Y_DELTA_Y = 1
Y_THETA = 2
Y_DELTA_X_DOT = 3
Y_DELTA_Y_DOT = 4
Y_THETA_DOT = 5

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
P_R0 = 15
P_MU = 16
P_OMEGA = 17
P_OMEGA_EARTH = 18
P_RHO1 = 19
P_RHO2 = 20
P_RHO3 = 21
