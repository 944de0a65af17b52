# Rope geometry of the capstan scenes on a continuous cylinder (b2b_demo):
# wrap angle theta about the z axis on the circle of radius rc, one element
# per 7.5 degrees, straight tangent leads of n_lead elements of the same
# length at both ends; for theta = 2 pi a helix of pitch p (leads along its
# tangent). Prints the polyline points.
import math, sys
theta_deg = float(sys.argv[1]); pitch = float(sys.argv[2]) if len(sys.argv) > 2 else 0.0
R, r, g0 = 0.5, 0.01, 1.0e-5
rc = R + r + 0.5 * g0
d = 7.5; n_wrap = round(theta_deg / d); n_lead = 4
th = math.radians(theta_deg); c = pitch / th if th > 0 else 0.0
dphi = th / n_wrap
phi0 = -math.pi / 2
def p(phi):
    return (rc * math.cos(phi), rc * math.sin(phi), c * (phi - phi0))
def t(phi):
    v = (-math.sin(phi), math.cos(phi), c / rc); n = math.sqrt(sum(x * x for x in v)); return tuple(x / n for x in v)
el = math.dist(p(phi0), p(phi0 + dphi))
pts = []
a = p(phi0); ta = t(phi0)
for k in range(n_lead, 0, -1):
    pts.append(tuple(a[i] - k * el * ta[i] for i in range(3)))
for k in range(n_wrap + 1):
    pts.append(p(phi0 + k * dphi))
b = p(phi0 + th); tb = t(phi0 + th)
for k in range(1, n_lead + 1):
    pts.append(tuple(b[i] + k * el * tb[i] for i in range(3)))
print('! %d points, element %.6f, rc %.8f, lead-in direction %s, lead-out direction %s' % (len(pts), el, rc, ta, tb), file=sys.stderr)
s = ',\n'.join('         %.15g, %.15g, %.15g' % q for q in pts)
print('      points =\n' + s + ' /')
