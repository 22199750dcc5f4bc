// Cushion rebound for the pool model: the rail's nose touches the ball
// above its centre. Five laws (CushionModel): han_2005_v0 (breakshot
// 0.1's law; first part below), han_2005 (the same impulse law with the
// slate's reaction, the default; second part), mathavan_2010 (third
// part), impulse_frictional (fourth part) and stronge_compliant (fifth
// part).
//
// PART 1, han_2005_v0 (H. Han, "Dynamics in carom and three cushion
// billiards", J. Mech. Sci. Tech. 19 (2005)). Every step below is derived
// here from impulse-momentum for a solid sphere (I = 2/5 m R^2) rather
// than copied from the paper, whose intermediate equations have typos.
//
// Frame. The rail's unit normal n points into the table. We work in a
// right-handed local frame with
//   x = -n        (horizontal, from the ball towards the rail),
//   y = z cross x (horizontal, along the rail),
//   z             (up).
// The ball moves into the rail: v_x > 0. Its velocity is horizontal
// (v_z = 0) and its spin w = (w_x, w_y, w_z) is arbitrary.
//
// Geometry. The nose touches the ball at height h = nose_height * 2R above
// the cloth, i.e. h - R above the centre, so the contact point is
//   r = R (cos t, 0, sin t),   sin t = h/R - 1 = 2 nose_height - 1,
// and the contact normal (unit, from the rail into the ball) is
//   N = -(cos t, 0, sin t).
// WPA's 63.5 % nose gives sin t = 0.27, t = 15.7 degrees.
//
// Velocity of the ball's surface at the contact: u = v + w x r, with
//   w x r = R (w_y sin t, w_z cos t - w_x sin t, -w_y cos t).
// Normal part: u . N = v . N = -v_x cos t (w x r is perpendicular to r),
// so the approach speed along the contact normal is
//   c = v_x cos t                                          (Han's c)
// and it does not depend on the spin. Tangent plane basis
//   t1 = (0, 1, 0),   t2 = (-sin t, 0, cos t)   (t2 points up the ball)
// gives the slip components
//   u1 = u . t1 = v_y + R (w_z cos t - w_x sin t),
//   u2 = u . t2 = -(v_x sin t + R w_y).
// (Han's s_x and s_y are -u2 and -u1.)
//
// Impulse. The rail gives the impulse P = m p at r, with the impulse per
// unit mass p = p_N N + p1 t1 + p2 t2. Then
//   dv = p,   dw = (r x P) / I = 5/(2R^2) (r x p).
// With p_x = -p_N cos t - p2 sin t, p_y = p1, p_z = -p_N sin t + p2 cos t:
//   r x p = R (-p1 sin t, p_x sin t - p_z cos t, p1 cos t)
//         = R (-p1 sin t, -p2, p1 cos t),
// so (the normal part has no lever arm, only friction turns the ball)
//   dw_x = -(5 / 2R) p1 sin t,   dw_y = -(5 / 2R) p2,   dw_z = (5 / 2R) p1 cos t.
// The slip changes by
//   du1 = p1 + R (dw_z cos t - dw_x sin t) = 7/2 p1,
//   du2 = -(dv_x sin t - dv_z cos t) - R dw_y = 7/2 p2,
// and the approach speed by d(u . N) = p_N. For a sphere the normal and
// the tangential problems decouple, and the tangential one is isotropic:
// a friction impulse only shortens the slip, never turns it, so the slip
// direction stays fixed during the impact and the two cases below are
// exact for Coulomb friction (no need to integrate over the impact as
// Mathavan et al. 2010 do, whose table contact couples the directions).
//
// Normal impulse (Newton's restitution e on the contact normal):
//   p_N = (1 + e) c                                         (Han's P_zE / m)
// Friction: the impulse that stops the slip is -(2/7) u_t, of size
// (2/7) |u_t| (Han's P_zS / m). Coulomb's law caps it at mu p_N:
//   stick, if (2/7) |u_t| <= mu p_N:  (p1, p2) = -(2/7) (u1, u2)
//   slide, otherwise:                 (p1, p2) = -mu p_N (u1, u2) / |u_t|
// (Han's condition compares P_zS with mu P_zE; some write-ups of the
// model drop the mu.) After a stick the contact point rolls on the nose;
// after a slide the slip has kept its direction and shrunk by
// (7/2) mu p_N.
//
// New state, in the local frame:
//   v_x' = v_x - p_N cos t - p2 sin t,   v_y' = v_y + p1,
//   w_x' = w_x - (5/2R) p1 sin t,  w_y' = w_y - (5/2R) p2,  w_z' = w_z + (5/2R) p1 cos t.
// The vertical velocity v_z' = -p_N sin t + p2 cos t is dropped: the ball
// stays on the cloth. When it points down (always so when mu < tan t, as
// with the defaults: friction cannot tip the impulse upwards) the cloth
// takes it with an impulse through the ball's lowest point, which has no
// lever arm about the centre, so the spin is unchanged. When it points up
// (friction beyond tan t with strong topspin) the ball would hop, which
// the model ignores. Han's model has no cloth friction during the impact.
//
// Last guard. The tilted impulse stops the motion along N only: with a
// very low restitution, a high nose or strong draw meeting high friction,
// v_x' can stay positive (into the rail). A ball cannot pass the rail and
// the cloth together, so v_x' is then set to 0 (an extra horizontal
// impulse through the centre; it only removes energy). Since p2 >= -mu p_N,
//   v_x' <= v_x (1 - (1 + e) cos t (cos t - mu sin t)),
// so with the default nose and friction it cannot trigger for e >= 0.13.
//
// Checks (tests/test_cushion.cpp): nose at the centre height (t = 0) with
// no friction gives plain reflection v_x' = -e v_x; kinetic energy never
// increases (the normal impulse loses (1 - e^2) of the normal energy,
// friction removes slip energy, dropping v_z and the guard only remove
// energy); the angular momentum about the contact point keeps its x and z
// components (every impulse of the rail acts at r; v_z does not enter
// those two components).
//
// What is wrong with it: the normal impulse (1 + e) c v_x is
// the one a ball free to move vertically would take; the cloth then
// removes the vertical velocity it gave. Straight in, with e = 1 and no
// friction, v_x' = v_x (1 - 2 c^2) = -0.854 v_x at the 63.5 % nose: the
// rail "keeps" energy that its restitution does not account for. Kept
// as the named legacy law so that earlier results replay exactly.
//
// Cushion height. Every law takes sin t = 2 nose_height - 1, or
// (height - R) / R when a height in metres is given (table.cushion_height),
// so that balls of any radius meet the same rail at their own angle.
//
// PART 2, han_2005: Han's law with the slate's reaction.
//
// Assumption: the ball stays on the cloth during the impact,
// so the slate supplies whatever vertical impulse keeps v_z = 0. That
// reaction acts through the lowest point, straight up, hence through the
// centre: it changes no spin. With no friction at the cloth (Han's model
// has none; Mathavan's adds it), the rail's impulse per unit mass
// p_N N + p1 t1 + p2 t2 plus the slate's P_C z (P_C = p_N s - p2 c) gives
//   dv_x = -p_N c - p2 s,   dv_y = p1,   dv_z = 0,
//   dw as in part 1: dw = (5/2R) (-p1 s, -p2, p1 c).
// The normal approach speed at the nose is v_x c (v_z = 0), so Newton's
// restitution on it, with the normal impulse alone, is
//   v_x c -> -e v_x c,  i.e.  p_N = (1 + e) v_x / c,  v_x -> -e v_x
// (not (1 + e) v_x c: the slate takes the vertical part, so only
// p_N c acts along x). Straight in, e = 1, no friction: v_x' = -v_x.
//
// Friction. Under the constraint the slip's response to a tangential
// impulse is no longer isotropic:
//   du1 = 7/2 p1,   du2 = -(dv_x s + R dw_y) = (5/2 + s^2) p2,
// and the normal impulse itself moves u2 (by p_N c s). Newton's law
// applied together with a sticking friction can then create energy (a
// stun ball would leave with v_x' = -v_x and new spin), so the two are
// applied in sequence, as Han's algebra does: first the normal impulse,
// then the friction impulse on the slip it leaves,
//   u1 = v_y + R (w_z c - w_x s),   u2 = -(v_x' s + R w_y),  v_x' = -e v_x,
// the impulse that stops it, q = -(u1 / (7/2), u2 / (5/2 + s^2)), capped
// by Coulomb at mu p_N: q -> q mu p_N / |q| when |q| > mu p_N. A friction
// impulse along a fraction a <= 1 of the stopping impulse changes the
// kinetic energy by -(a - a^2/2) u.K^-1 u <= 0, so the law never creates
// energy; the normal step loses (1 - e^2) of the normal energy. Then
//   v_x'' = -e v_x - q2 s,  v_y' = v_y + q1,
//   w' = w + (5/2R) (-q1 s, -q2, q1 c),
// and the last guard of part 1 (v_x'' <= 0). The slate's reaction
// p_N s - q2 c is positive unless mu > tan t (0.28 at the 63.5 % nose):
// beyond that the ball would hop, which this step of the model does not
// follow (the vertical velocity stays 0).
//
// PART 3, mathavan_2010: S. Mathavan, M. R. Jackson, R. M. Parkin, "A
// theoretical analysis of billiard ball dynamics under cushion impacts",
// Proc. IMechE C 224 (2010) 1863-1873. The same geometry and constraint
// as part 2 (the paper: the ball does not leave the table, z_G' = 0), and
// sliding friction at the cloth as well: mu_w at the nose (I), mu_s at
// the cloth (C). The impact is integrated over the accumulated normal
// impulse P_I (the paper's independent variable), in steps dP:
//   slip at I:  u1 = v_y + R (w_z c - w_x s),  u2 = -(v_x s + R w_y)
//   slip at C:  a_x = v_x - R w_y,  a_y = v_y + R w_x
//   friction at I:  f = -min(mu_w dP, 2/7 |u|) u / |u|      (components f1, f2)
//   slate reaction:  dP_C = dP s - f2 c   (the paper's dP_I (sin t +
//                    mu_w sin Phi cos t); taken as 0 if negative)
//   friction at C:  g = -min(mu_s dP_C, 2/7 |a|) a / |a|
//   dv_x = -dP c - f2 s + g_x,   dv_y = f1 + g_y,
//   dw = (5/2R) (-f1 s + g_y, -f2 - g_x, f1 c).
// The cap 2/7 |slip| is the discrete form of the paper's rolling
// conditions (its eq. 15: no friction impulse while a contact rolls):
// it is the impulse that would just stop that contact's slip (the slip at
// C answers 7/2 g, at I at least (5/2 + s^2) f), so the slip is brought
// to rest instead of chattering about zero. Directions are those at the
// start of each step (the paper's explicit scheme).
// Compression lasts while the nose's normal approach speed v_x c is
// positive; the work of the normal force is accumulated by the
// trapezoidal rule (the paper's eq. 16a), dW = dP c (v_x + v_x') / 2, and
// the restitution phase goes on until the work done during it reaches
// e^2 times the compression's (the paper's energetic restitution, eq.
// 16b). The step is (1 + e) v_x / c / 5000 (the paper's starting estimate
// of the total impulse over its N = 5000). The step that ends compression
// is shortened to end at v_x = 0 (v_x is linear in P within a step), and
// the last restitution step to end at the target work (the work is
// quadratic in the step within it; its root is taken with sqrt).
// Constants: e = 0.98, mu_w = 0.14 are the paper's fit to its own
// measurements; the contact height h = 7R/5 is the paper's; mu_s is the
// cloth's sliding friction (the paper's 0.212; in a simulation,
// physics.sliding_friction).
//
// PART 4, impulse_frictional: one rigid-body impulse at the nose, the
// kind of law pooltool calls "impulse_frictional_inelastic" (a sphere
// hitting a half-space whose normal is the contact normal: Newton's
// restitution along it, Coulomb friction capped by the impulse that
// stops the slip). Pooltool solves it for a free sphere and then drops
// the vertical velocity; for a free sphere that is part 1's law exactly,
// with its defect (0.854 of the speed straight in, e = 1, no friction).
// Here the ball is held on the cloth during the impulse, as in part 2.
//
// The constrained ball. The slate's frictionless reaction P_C z acts
// through the centre and keeps v_z = 0. A rail impulse per unit mass
// p = p_N N + p1 t1 + p2 t2 then changes the nose's contact velocity
// (u_N = u . N, u1, u2 as in part 1) by K p, with (from part 2's dv, dw)
//   du_N = c^2 p_N + c s p2,   du1 = 7/2 p1,   du2 = c s p_N + (5/2 + s^2) p2.
// K is symmetric positive definite: it is the constrained ball's inverse
// mass at the nose, and an impulse p changes the kinetic energy per unit
// mass by p . u + 1/2 p . K p (the slate's impulse does no work: v_z
// stays 0). The coupling c s is what makes this law differ from a free
// sphere's: a normal impulse turns the ball's horizontal motion round, and
// the contact point then slides along the tilted nose (u2 changes).
//
// Newton's restitution on the final normal velocity: u_N' = -e u_N, i.e.
// (u_N = -v_x c, v_z = 0 before and after)
//   v_x' = -e v_x,
// whatever the friction: the friction's own normal part is made up by the
// rail's normal impulse, p_N = (1 + e) v_x / c - (s / c) p2. With that,
// the slip left after an impulse with tangential part q = (p1, p2) is
//   u_t' = w + S q,   w = (u1, e v_x s - R w_y),   S = diag(7/2, 5/2),
// where w is the slip a frictionless impulse would leave (u2 evaluated at
// v_x' = -e v_x, as in part 2) and S = K_tt - K_tn K_nt / K_nn is the
// tangential response with the normal velocity held. The impulse that
// stops the slip is q* = -g, g = S^-1 w = (u1 / (7/2), w2 / (5/2)). The
// law takes q = -a g with the largest fraction a in [0, 1] that meets both
// of the following.
//
// Coulomb: |q| <= mu p_N. With q = -a g, p_N = P0 + a (s / c) g2, P0 =
// (1 + e) v_x / c, this is a (|g| - mu (s/c) g2) <= mu P0, so
//   a <= mu P0 / (|g| - mu (s/c) g2)   when |g| - mu (s/c) g2 > 0
// (otherwise the friction raises its own normal impulse faster than it
// grows, and Coulomb sets no bound). When the bound is below 1 the ball
// slides along the direction of the stopping impulse (as in part 2; for a
// slip along t1 or t2 alone that is straight against the slip).
//
// Energy. Newton's law on the final velocity together with friction can
// create energy (Kane's paradox; Stronge, "Impact Mechanics", 2000): the
// extra normal impulse -(s/c) p2 that holds v_x' = -e v_x works against
// the separating speed. From the energy formula above, the frictionless
// impulse changes the energy by -1/2 (1 - e^2) v_x^2 and the friction
// adds
//   dE_f(a) = -(a - a^2/2) W + a e v_x s g2,   W = w . g = u1^2/(7/2) + w2^2/(5/2).
// A full stick (a = 1) thus changes the energy by
//   -1/2 (1 - e^2) v_x^2 - u1^2 / 7 - (R w_y)^2 / 5 + (e v_x s)^2 / 5,
// which is positive for a ball without topspin driven straight in once
// e > 1 / sqrt(1 + 2 s^2 / 5) (0.986 at the 63.5 % nose, 0.970 at 70 %).
// The law does not let the impact create energy: with D = 1/2 (1 - e^2)
// v_x^2 and L = e v_x s g2, the total change 1/2 W a^2 - (W - L) a - D
// must stay <= 0, i.e. a <= a+, the quadratic's larger root
//   a+ = ((W - L) + sqrt((W - L)^2 + 2 W D)) / W
// (evaluated as 2 D / (sqrt(...) - (W - L)) when W - L < 0, free of
// cancellation). a+ >= 1 whenever L <= W/2 + D (always when L <= 0: at
// t = 0, and for a nose above the centre whenever g2 <= 0, i.e. topspin
// w_y at least e v_x s / R, a rolling ball among them). With e = 1 and a
// ball without topspin straight in, a+ = 0: no friction at all.
//
// New state: v_x' = -e v_x, v_y' = v_y + p1, w' = w + (5/2R) (-p1 s, -p2,
// p1 c). After a stick the nose's contact point does not slip (u_t' = 0).
// At t = 0 the law is plain reflection (v_x' = -e v_x) with the sphere's
// Coulomb friction at its equator: p1 = -sign(u1) min(u1 / (7/2), mu (1 +
// e) v_x) when w_y = 0. The slate's reaction p_N s - p2 c is not checked
// for sign: a ball that friction would lift is kept on the cloth, as in
// part 2. No guard on v_x' is needed (e >= 0).
//
// PART 5, stronge_compliant: a compliant contact at the nose. Sources:
// W. J. Stronge, "Impact Mechanics", Cambridge UP 2000 (2nd ed. 2018),
// ch. 5, "Tangential compliance in planar impact of rough bodies";
// W. J. Stronge, "Rigid body collisions with friction", Proc. R. Soc.
// Lond. A 431 (1990) 169-181 (the energetic coefficient of restitution);
// W. J. Stronge, R. James, B. Ravani, "Oblique impact with friction and
// tangential compliance", Phil. Trans. R. Soc. Lond. A 359 (2001)
// 2447-2465 (the ratio eta^2 of normal to tangential stiffness, the
// stick/slip regimes, the reversal of the slip); pooltool's
// stronge_compliant law (github ekiefl/pooltool) follows the 2018 book's
// chapter 5 for a free sphere on a half-space.
//
// The contact. Between the rail and the ball sits a massless contact
// particle tied to the rail by a normal spring and a tangential spring,
// the latter in series with a Coulomb slider (the book's model):
//   normal force per unit mass   F = k x        while compressing,
//                                F = (k/e^2)(x - (1 - e^2) x_m)  after,
// (x the normal compression, x_m its largest value: the spring unloads
// e^-2 times stiffer than it loaded, so it gives back e^2 of the energy
// it stored: Stronge's energetic restitution e, which cannot create
// energy, unlike Newton's law with friction);
//   tangential force per unit mass  f = -kt d,  |f| <= mu F,
// d the tangential spring's stretch (a vector in the tangent plane). While
// |kt d| < mu F the particle sticks to the ball and d grows at the slip
// rate u_t of the ball's surface; when the cap is reached the slider
// slips and d stays on the circle |kt d| = mu F. The parameter is
//   eta^2 = k / kt   (CushionParams::compliance_ratio),
// the ratio of tangential to normal compliance; the contact ends when F
// returns to 0. k drops out: scaling k scales time alone (below).
//
// The ball held on the cloth. As in part 4, the slate's frictionless
// reaction through the centre keeps v_z = 0, and a rail impulse per unit
// mass p = p_N N + p1 t1 + p2 t2 moves the nose's approach speed
// a = v_x c (= -u . N) and slip (u1, u2) by
//   da = -(c^2 p_N + c s p2),  du1 = 7/2 p1,  du2 = c s p_N + (5/2 + s^2) p2,
// the inverse of the constrained ball's mass at the nose. So in time:
//   x' = a,  a' = -(c^2 F + c s f2),  u1' = 7/2 f1,  u2' = c s F + (5/2 + s^2) f2,
//   d' = u_t while sticking.
// For a free sphere (pooltool's case, or this one at t = 0 along t1) the
// three directions decouple with inverse masses 1, 7/2, 7/2 and the book's
// closed forms hold: x = (a0 / w) sin(w t) with w^2 = k, the compression
// lasting pi / (2w) and the restitution e pi / (2w), the ball leaving at
// -e a0. Sticking from the start (possible when u0 / a0 <= mu eta^2,
// since then |kt d| = kt u0 t stays below mu F = mu k a0 t at first), the
// slip oscillates, u(t) = u0 cos(wt t) with wt^2 = (7/2) kt = (7/2) k /
// eta^2: the slip reverses when the impact lasts longer than a quarter
// of the tangential period, and a perfectly rough elastic sphere
// (mu -> infinity, e = 1) leaves with u0 cos(pi sqrt(7/2 / eta^2)), -u0
// at eta^2 = 7/2 (the tangential and normal periods equal). Slipping from
// the start to the end (u0 / a0 > mu ((1 + e) 7/2 - eta^2 / e): the slip
// never falls to the rate at which the shrinking cap pulls the spring
// back, d' = -mu F' / kt, which is largest at the end, mu e^-1 a0 w^2 /
// kt), the friction is mu F throughout and u_f = u0 - (7/2) mu (1 + e) a0,
// the rigid law's Coulomb slide. When kt -> infinity (eta^2 -> 0) the
// spring's stretch and its stored energy vanish and the law becomes the
// rigid one with Coulomb friction and energetic restitution (part 3's
// nose without cloth friction).
//
// Held on the cloth, the normal and the t2 directions couple (c s), so
// there is no closed form; the law integrates the equations above in
// time. Units: k = 1 (time in units of 1/sqrt(k)); with kt = 1/eta^2
// every result is independent of k, and proportional to the speed. Steps:
//   1. the tangential force of the stretch at the step's start,
//      f = -kt d (already within the cap), held over the step;
//   2. the normal oscillator x'' = -c^2 K x - c s f2 (K = 1, or 1/e^2 after
//      the compression, x measured from the unloaded length) advanced
//      exactly: about its shifted centre x_q = -s f2 / (c K) it turns by
//      the angle W h, W = c sqrt(K); its impulse over the step follows from
//      a's change: J = -((a_new - a) + c s f2 h) / c^2;
//   3. the slip takes the step's impulses: u1 += 7/2 f1 h,
//      u2 += c s J + (5/2 + s^2) f2 h;
//   4. the stretch follows the new slip, d += h u_t, and is brought back
//      onto the circle |kt d| = mu F_new if it left it (the slider slips,
//      along the spring's force: Coulomb's law with isotropic friction).
// Steps 1 and 4 are the symplectic Euler scheme (no numerical damping of
// the tangential oscillation); the friction lags the cap by one step, a
// left Riemann sum of F whose O(h) error, -h/2 times F's change, cancels
// over the impact (F is 0 at both ends) as long as h stays the same: the
// restitution keeps the compression's h (turning its oscillator, 1/e
// times faster, by pi / (2 n e) a step) when e >= 1/2, and takes 2 e h
// below (pi / n a step). The compression's step turns the normal
// oscillator by pi / (2 n), n = 256. The compression ends
// in the step where a changes sign, the restitution where x does: that
// step is redone with the fraction a / (a - a_new) (x / (x - x_new)) of
// its length, so that, with no friction, both phases end after n steps
// up to rounding and the ball leaves with -e v_x. cos and sin of the
// step's angle come from their Taylor series (|angle| <= pi/256: the
// truncation is below 1e-25). The error is first order in the step (the
// stick/slip changes fall within steps, and a spring still loaded when
// the cap closes is released over a step): over incidences 0-85 degrees
// with rolling, stun and side spin at 1 m/s, n = 256 differs from 8192 by
// at most 2.5e-4 m/s in any velocity component. e = 0 ends the impact at the largest
// compression. A guard of 16 n steps per phase stops nonsense input; if
// the compression never ends, v_x' is set to 0 as in part 1.
//
// From the total impulses (P_N, P1, P2), as in part 2:
//   v_x' = v_x - P_N c - P2 s,  v_y' = v_y + P1,  w' = w + (5/2R)(-P1 s, -P2, P1 c).
// The springs store energy only during the impact: F = 0 at its end, so
// the cap forces d to 0 and the slider dissipates what the tangential
// spring held; the normal spring keeps (1 - e^2) of the compression's
// work. The law therefore creates no energy, up to the scheme's error:
// at most 1e-8 of it, found with e = 1 and a sticking contact, where the
// exact law keeps it all (tests/test_cushion_stronge.cpp). Restitution re-loading (a > 0 again after the
// compression, which friction can cause through c s) follows the
// unloading line. The slate's reaction is not checked for sign (parts 2
// and 4 do the same).
//
// pooltool's choices (read from its source, not copied): a free sphere
// at the tilted contact (inverse masses 1 and 7/2, the vertical velocity
// dropped after: part 1's defect), the closed forms above with roots
// found numerically, defaults e = 0.85, mu = 0.2, omega_t / omega_n = 1.8
// (eta^2 = 3.5 / 1.8^2 = 1.080), its pool table's cushion at 0.64 of the
// ball's diameter. Here the ball stays on the cloth, which couples the
// directions; the restitution and eta^2 default to pooltool's, the
// friction and the nose height are the table's (0.14, 0.635).
//
// The mass cancels: every impulse is proportional to it. Only sqrt is
// used, so results are bit-identical wherever IEEE doubles are (the
// build has -ffp-contract=off).
#include "breakshot/pool.hpp"

#include <algorithm>
#include <cmath>

namespace breakshot {

std::string_view cushion_model_name(CushionModel m) {
  switch (m) {
    case CushionModel::han_2005_v0:
      return "han_2005_v0";
    case CushionModel::han_2005:
      return "han_2005";
    case CushionModel::mathavan_2010:
      return "mathavan_2010";
    case CushionModel::impulse_frictional:
      return "impulse_frictional";
    case CushionModel::stronge_compliant:
      return "stronge_compliant";
  }
  return "han_2005_v0";
}

bool parse_cushion_model(std::string_view name, CushionModel& out) {
  for (const CushionModel m : kCushionModels) {
    if (name == cushion_model_name(m)) {
      out = m;
      return true;
    }
  }
  return false;
}

namespace {

/// The ball's state in the cushion's local frame (x towards the rail, y
/// along it, z up).
struct Local {
  double vx, vy, wx, wy, wz;
};

/// Part 1: breakshot 0.1's law, unchanged.
Local han_2005_v0(Local b, double R, double s, double c, double e, double mu) {
  const double vx = b.vx;
  const double vy = b.vy;
  const double wx = b.wx;
  const double wy = b.wy;
  const double wz = b.wz;

  // Normal impulse per unit mass.
  const double pn = (1.0 + e) * vx * c;

  // Slip of the contact point in the tangent plane (t1, t2).
  const double u1 = vy + R * (wz * c - wx * s);
  const double u2 = -(vx * s + R * wy);
  const double slip = std::sqrt(u1 * u1 + u2 * u2);

  double p1 = 0.0;
  double p2 = 0.0;
  const double limit = mu * pn;
  if (2.0 / 7.0 * slip <= limit) {  // the slip stops: sticking
    p1 = -2.0 / 7.0 * u1;
    p2 = -2.0 / 7.0 * u2;
  } else {  // sliding throughout, along the initial slip direction
    const double k = limit / slip;
    p1 = -k * u1;
    p2 = -k * u2;
  }

  double vx2 = vx - pn * c - p2 * s;
  const double vy2 = vy + p1;
  if (vx2 > 0.0) vx2 = 0.0;  // the rail and the cloth together stop it

  const double q = 2.5 / R;
  return {vx2, vy2, wx - q * s * p1, wy - q * p2, wz + q * c * p1};
}

/// Part 2: Han's law with the slate's reaction.
Local han_2005(Local b, double R, double s, double c, double e, double mu) {
  const double pn = (1.0 + e) * b.vx / c;  // normal impulse per unit mass
  const double vx1 = -e * b.vx;             // after the normal impulse
  const double u1 = b.vy + R * (b.wz * c - b.wx * s);
  const double u2 = -(vx1 * s + R * b.wy);
  double q1 = -u1 / 3.5;
  double q2 = -u2 / (2.5 + s * s);
  const double size = std::sqrt(q1 * q1 + q2 * q2);
  const double limit = mu * pn;
  if (size > limit) {  // sliding: Coulomb's cap
    const double k = limit / size;
    q1 *= k;
    q2 *= k;
  }
  double vx2 = vx1 - q2 * s;
  if (vx2 > 0.0) vx2 = 0.0;
  const double q = 2.5 / R;
  return {vx2, b.vy + q1, b.wx - q * s * q1, b.wy - q * q2, b.wz + q * c * q1};
}

/// Friction impulse against the slip (x, y): size min(limit, 2/7 |slip|).
void friction(double x, double y, double limit, double& fx, double& fy) {
  const double slip = std::sqrt(x * x + y * y);
  fx = 0.0;
  fy = 0.0;
  if (!(slip > 0.0) || !(limit > 0.0)) return;
  const double size = std::min(limit, 2.0 / 7.0 * slip);
  fx = -size * x / slip;
  fy = -size * y / slip;
}

struct MathavanStep {
  double R, s, c, mu_w, mu_s;

  /// One step of normal impulse dp (per unit mass) from state b.
  Local operator()(const Local& b, double dp) const {
    const double u1 = b.vy + R * (b.wz * c - b.wx * s);
    const double u2 = -(b.vx * s + R * b.wy);
    double f1 = 0.0;
    double f2 = 0.0;
    friction(u1, u2, mu_w * dp, f1, f2);
    double pc = dp * s - f2 * c;  // the slate's reaction
    if (pc < 0.0) pc = 0.0;
    const double ax = b.vx - R * b.wy;
    const double ay = b.vy + R * b.wx;
    double gx = 0.0;
    double gy = 0.0;
    friction(ax, ay, mu_s * pc, gx, gy);
    const double q = 2.5 / R;
    return {b.vx - dp * c - f2 * s + gx, b.vy + f1 + gy, b.wx + q * (-f1 * s + gy),
            b.wy + q * (-f2 - gx), b.wz + q * f1 * c};
  }
};

constexpr int kMathavanSteps = 5000;      // the paper's N
constexpr int kMathavanMaxSteps = 200000;  // a guard against nonsense parameters

/// Part 3: Mathavan et al. 2010.
Local mathavan_2010(Local b, double R, double s, double c, double e, double mu_w,
                    double mu_s) {
  const MathavanStep step{R, s, c, mu_w, mu_s};
  const double dp = (1.0 + e) * b.vx / c / kMathavanSteps;
  // Compression: while the nose's normal approach speed v_x c > 0.
  double work = 0.0;
  int n = 0;
  while (b.vx > 0.0 && n < kMathavanMaxSteps) {
    Local next = step(b, dp);
    double h = dp;
    if (!(next.vx > 0.0)) {  // ends within this step: v_x is linear in P
      h = dp * (b.vx / (b.vx - next.vx));
      next = step(b, h);
      next.vx = 0.0;
    }
    work += h * c * 0.5 * (b.vx + next.vx);
    b = next;
    ++n;
  }
  if (b.vx > 0.0) b.vx = 0.0;  // the guard stopped it: the rail holds the ball
  // Restitution: until the work done since compression ended reaches
  // e^2 times the compression's.
  const double target = e * e * work;
  double done = 0.0;
  n = 0;
  while (done < target && n < kMathavanMaxSteps) {
    Local next = step(b, dp);
    const double a0 = -b.vx;  // speed away from the rail
    const double a1 = -next.vx;
    const double dw = dp * c * 0.5 * (a0 + a1);
    if (done + dw >= target) {
      // W(h) = c (a0 h + k h^2 / 2) with k = (a1 - a0) / dp; solve
      // W(h) = rest for h in (0, dp] in a form free of cancellation.
      const double rest = target - done;
      const double k = (a1 - a0) / dp;
      const double root = std::sqrt(a0 * a0 * c * c + 2.0 * c * k * rest);
      double h = a0 * c + root > 0.0 ? 2.0 * rest / (a0 * c + root) : dp;
      if (!(h > 0.0) || h > dp) h = dp;
      b = step(b, h);
      break;
    }
    done += dw;
    b = next;
    ++n;
  }
  if (b.vx > 0.0) b.vx = 0.0;
  return b;
}

/// Part 4: one frictional impulse with the slate's reaction.
Local impulse_frictional(Local b, double R, double s, double c, double e, double mu) {
  const double p0 = (1.0 + e) * b.vx / c;  // the frictionless normal impulse
  // The slip a frictionless impulse would leave, and the stopping impulse -g.
  const double w1 = b.vy + R * (b.wz * c - b.wx * s);
  const double w2 = e * b.vx * s - R * b.wy;
  const double g1 = w1 / 3.5;
  const double g2 = w2 / 2.5;
  const double size = std::sqrt(g1 * g1 + g2 * g2);
  double a = 0.0;
  if (size > 0.0) {
    a = 1.0;
    // Coulomb: a (|g| - mu (s/c) g2) <= mu P0.
    const double grows = size - mu * (s / c) * g2;
    if (grows > 0.0 && a * grows > mu * p0) a = mu * p0 / grows;
    // No energy created: a <= a+, the larger root of
    // 1/2 W a^2 - (W - L) a - D.
    const double W = w1 * g1 + w2 * g2;
    const double L = e * b.vx * s * g2;
    const double D = 0.5 * (1.0 - e * e) * b.vx * b.vx;
    const double k = W - L;
    const double root = std::sqrt(k * k + 2.0 * W * D);
    const double top = k >= 0.0 ? (k + root) / W : 2.0 * D / (root - k);
    if (a > top) a = top;
  }
  const double p1 = -a * g1;
  const double p2 = -a * g2;
  const double q = 2.5 / R;
  return {-e * b.vx, b.vy + p1, b.wx - q * s * p1, b.wy - q * p2, b.wz + q * c * p1};
}

/// cos and sin of a small angle (|a| <= pi/256) from their Taylor series.
void cos_sin_small(double a, double& co, double& si) {
  const double a2 = a * a;
  co = 1.0 - a2 / 2.0 * (1.0 - a2 / 12.0 * (1.0 - a2 / 30.0 * (1.0 - a2 / 56.0)));
  si = a * (1.0 - a2 / 6.0 * (1.0 - a2 / 20.0 * (1.0 - a2 / 42.0 * (1.0 - a2 / 72.0))));
}

constexpr int kStrongeSteps = 256;  // steps per phase (a quarter turn)
constexpr double kStrongeAngle = 3.14159265358979323846 / (2.0 * kStrongeSteps);

/// The compliant contact's state during the impact (part 5), per unit
/// mass, k = 1.
struct Compliant {
  double x;       // normal spring stretch beyond its unloaded length
  double a;       // approach speed along the normal, v_x c
  double u1, u2;  // slip
  double d1, d2;  // tangential spring stretch
  double pn, p1, p2;  // impulses so far
};

struct StrongeStep {
  double s, c, mu, kt;

  /// One step of time h at normal stiffness K (1 or 1/e^2), turning the
  /// normal oscillator by the angle `angle`.
  Compliant operator()(const Compliant& b, double K, double h, double angle) const {
    const double f1 = -kt * b.d1;
    const double f2 = -kt * b.d2;
    const double W = angle / h;                // c sqrt(K)
    const double xq = -s * f2 / (c * K);       // the shifted centre
    double co = 0.0;
    double si = 0.0;
    cos_sin_small(angle, co, si);
    const double y = b.x - xq;
    const double y2 = y * co + b.a / W * si;
    const double a2 = b.a * co - W * y * si;
    const double J = -((a2 - b.a) + c * s * f2 * h) / (c * c);
    Compliant n = b;
    n.x = y2 + xq;
    n.a = a2;
    n.u1 = b.u1 + 3.5 * f1 * h;
    n.u2 = b.u2 + c * s * J + (2.5 + s * s) * f2 * h;
    n.d1 = b.d1 + h * n.u1;
    n.d2 = b.d2 + h * n.u2;
    const double F = n.x > 0.0 ? K * n.x : 0.0;
    const double cap = mu * F;
    const double g1 = kt * n.d1;
    const double g2 = kt * n.d2;
    const double g = g1 * g1 + g2 * g2;
    if (g > cap * cap) {  // the slider slips: back onto the circle
      const double k = cap / std::sqrt(g);
      n.d1 *= k;
      n.d2 *= k;
    }
    n.pn = b.pn + J;
    n.p1 = b.p1 + f1 * h;
    n.p2 = b.p2 + f2 * h;
    return n;
  }
};

/// Part 5: Stronge's compliant contact with the slate's reaction.
Local stronge_compliant(Local b, double R, double s, double c, double e, double mu,
                        double eta2) {
  const StrongeStep step{s, c, mu, 1.0 / eta2};
  Compliant st{0.0, b.vx * c, b.vy + R * (b.wz * c - b.wx * s), -(b.vx * s + R * b.wy),
               0.0, 0.0, 0.0, 0.0, 0.0};
  // Compression: K = 1, W = c.
  const double h = kStrongeAngle / c;
  bool compressed = false;
  for (int n = 0; n < 16 * kStrongeSteps; ++n) {
    const Compliant next = step(st, 1.0, h, kStrongeAngle);
    if (next.a > 0.0) {
      st = next;
      continue;
    }
    const double frac = st.a / (st.a - next.a);
    st = step(st, 1.0, h * frac, kStrongeAngle * frac);
    compressed = true;
    break;
  }
  // Below 1e-100 the restitution returns at most 1e-200 of the energy:
  // nothing a double can show, and 1/e^2 would overflow.
  if (compressed && e > 1e-100 && st.x > 0.0) {
    // Restitution: the spring unloads with stiffness 1/e^2 from the
    // largest compression x_m; its stretch beyond the unloaded length
    // (1 - e^2) x_m is e^2 x_m, so the force x_m is continuous.
    const double K = 1.0 / (e * e);
    const double hr = e >= 0.5 ? h : 2.0 * e * h;
    const double angle = hr * c / e;
    st.x *= e * e;
    for (int n = 0; n < 16 * kStrongeSteps; ++n) {
      const Compliant next = step(st, K, hr, angle);
      if (next.x > 0.0) {
        st = next;
        continue;
      }
      const double frac = st.x / (st.x - next.x);
      st = step(st, K, hr * frac, angle * frac);
      break;
    }
  }
  double vx2 = b.vx - st.pn * c - st.p2 * s;
  if (vx2 > 0.0) vx2 = 0.0;  // only when the guard stopped the compression
  const double q = 2.5 / R;
  return {vx2, b.vy + st.p1, b.wx - q * s * st.p1, b.wy - q * st.p2, b.wz + q * c * st.p1};
}

}  // namespace

CushionImpact cushion_impact(Vec2 v, Vec3 w, Vec2 n, double mass, double radius,
                             const CushionParams& params) {
  static_cast<void>(mass);  // cancels out, see above
  const Vec2 ex = -(n / norm(n));  // towards the rail
  const Vec2 ey = perp(ex);        // along the rail; (ex, ey, z) right-handed

  const double vx = dot(v, ex);
  if (!(vx > 0.0)) return {v, w};  // not moving into the rail: no impact
  const Vec2 wh{w.x, w.y};
  const Local in{vx, dot(v, ey), dot(wh, ex), dot(wh, ey), w.z};

  const double R = radius;
  const double s = params.height > 0.0 ? (params.height - R) / R   // sin t
                                       : 2.0 * params.nose_height - 1.0;
  const double c = std::sqrt(1.0 - s * s);  // cos t
  const double e = params.restitution;
  const double mu = params.friction;

  Local out{};
  switch (params.model) {
    case CushionModel::han_2005_v0:
      out = han_2005_v0(in, R, s, c, e, mu);
      break;
    case CushionModel::han_2005:
      out = han_2005(in, R, s, c, e, mu);
      break;
    case CushionModel::mathavan_2010:
      out = mathavan_2010(in, R, s, c, e, mu, params.cloth_friction);
      break;
    case CushionModel::impulse_frictional:
      out = impulse_frictional(in, R, s, c, e, mu);
      break;
    case CushionModel::stronge_compliant:
      out = stronge_compliant(in, R, s, c, e, mu, params.compliance_ratio);
      break;
  }

  CushionImpact r;
  r.velocity = ex * out.vx + ey * out.vy;
  const Vec2 wh2 = ex * out.wx + ey * out.wy;
  r.spin = {wh2.x, wh2.y, out.wz};
  return r;
}

}  // namespace breakshot
