/* SPDX-License-Identifier: MIT */
/*
 * The parameter effects of Kasakura's Fig. 4.5 and 4.6 (issue 16, docs/vines.md
 * "Parameter effects"): the base shape (Table 4.1) and each variant of the captions grown
 * on the same pole, each effect measured against the base.
 *
 * Fig. 4.5, growth: (b) internode 100: the leaves farther apart, in proportion; (c) radius
 * 4: a thicker stem, the helix wider by the radius's change; (d) twining right: the
 * mirror image; (e) step_time 5: the apex reaches farther before it twines; (f) angle 30:
 * a wider spread, a tighter pitch; (g) free_nodes 2: a longer straight stem.
 * Fig. 4.6, the model: (b) no cotyledons nor leaves; (c) two cotyledons; (d) two leaves a
 * node; (f) leaf size 25. Those four leave the growth as it was, bit for bit.
 */
#include <stdlib.h>
#include <string.h>

#include "mesh.h"
#include "test.h"
#include "vine.h"
#include "vine_test.h"

#define DEG (VEC_PI / 180.0)

/* The pole: radius R, 1 m tall, 64 sides; the vine planted GAP from its side (as
 * test_vine_grow's), its twined part measured below the top's rim. */
static const double R = 0.02, H = 1.0, GAP = 0.015, RIM = 0.95;

/* Fig. 4.5(a) and 4.6(a): Table 4.1 (4.2 is the same), one thesis unit a millimetre:
 * vine_params_default, which the table's values are (checked here). */
static struct vine_params base(void)
{
	struct vine_params p;

	vine_params_default(&p);
	CHECK(p.internode == 0.060 && p.radius == 0.002 && p.step_time == 10 && p.angle == 18);
	CHECK(p.free_nodes == 1 && p.twining == VINE_LEFT && p.leaves_per_node == 1 &&
	      p.cotyledons == 1 && p.leaf_size == 0.012);
	return p;
}

/* p grown to its end on s (NULL: nothing to climb) from plant. */
static void grow(struct vine *v, const struct vine_params *p, const struct vine_support *s,
		 struct vec3 plant)
{
	CHECK_INT(vine_params_check(p, NULL, NULL), 0);
	vine_init(v, p, plant);
	CHECK_INT(vine_grow(v, s, 1e9), 0);
	CHECK(vine_done(v));
}

static struct vec3 beside(void)
{
	return vec3(R + GAP, 0, 0);
}

/* The main axis's helix on the pole, its radius within 0.1 r of R + r. */
static struct helix helix_of(const struct vine *v)
{
	struct helix h;

	CHECK(pole_helix(&v->shoots[0], RIM, &h));
	CHECK(fabs(h.turned) > 3 * VEC_PI); /* a turn and a half at least */
	CHECK_NEAR(h.radius_min, R + v->p.radius, 0.1 * v->p.radius);
	CHECK_NEAR(h.radius_max, R + v->p.radius, 0.1 * v->p.radius);
	return h;
}

/* The raw axes of a and b, the same bit for bit. */
static bool same_growth(const struct vine *a, const struct vine *b)
{
	if (a->nshoots != b->nshoots)
		return false;
	for (size_t k = 0; k < a->nshoots; k++) {
		const struct vine_shoot *x = &a->shoots[k], *y = &b->shoots[k];

		if (x->n != y->n || x->parent != y->parent || x->node != y->node ||
		    memcmp(x->axis, y->axis, x->n * sizeof(*x->axis)) != 0 ||
		    memcmp(x->contact, y->contact, x->n) != 0)
			return false;
	}
	return true;
}

static size_t leaves_of(const struct vine *v, struct vine_leaf **l)
{
	size_t n;

	CHECK_INT(vine_leaves(v, l, &n), 0);
	return n;
}

/* The main axis's node k on the smoothed axis a: its distance along the drawn stem from
 * node k - 1. */
static double internode_along(const struct vine *v, const struct vec3 *a, size_t k)
{
	size_t d = (size_t)v->p.points_per_internode;
	double s = 0;

	for (size_t i = (k - 1) * d; i < k * d; i++)
		s += vec3_dist(a[i], a[i + 1]);
	return s;
}

/*
 * Fig. 4.5(b): internode 60 -> 100. The leaves sit on the nodes; between consecutive nodes
 * of the twined main axis, the drawn stem's length and the straight distance (what one
 * sees), their means. The raw axis's node spacing is l exactly.
 */
static void test_internode(const struct vine_support *s)
{
	struct vine_params p[2] = { base(), base() };
	double along[2], chord[2];

	p[1].internode = 0.100;
	for (int k = 0; k < 2; k++) {
		struct vine v;
		struct vine_leaf *l;
		struct vec3 *a;
		struct helix h;
		size_t nl, d = (size_t)p[k].points_per_internode, pairs = 0;

		grow(&v, &p[k], s, beside());
		h = helix_of(&v);
		CHECK_INT(vine_smooth(&v, 0, &a), 0);
		nl = leaves_of(&v, &l);
		for (size_t i = 0; i < nl; i++)
			if (l[i].shoot == 0)
				CHECK(vec3_dist(l[i].p[0], a[l[i].node * d]) == 0);
		along[k] = chord[k] = 0;
		for (size_t n = 1; n <= vine_shoot_nodes(&v, 0); n++) {
			double raw = 0;

			for (size_t i = (n - 1) * d; i < n * d; i++)
				raw += vec3_dist(v.shoots[0].axis[i], v.shoots[0].axis[i + 1]);
			CHECK_NEAR(raw, p[k].internode, 1e-12);
			if ((n - 1) * d < h.first || n * d > h.last)
				continue;
			along[k] += internode_along(&v, a, n);
			chord[k] += vec3_dist(a[(n - 1) * d], a[n * d]);
			pairs++;
		}
		CHECK(pairs >= 5);
		along[k] /= (double)pairs;
		chord[k] /= (double)pairs;
		printf("4.5(b) internode %.3f m: %zu internodes on the helix, their nodes %.5f m "
		       "apart along the stem, %.5f m straight\n", p[k].internode, pairs, along[k],
		       chord[k]);
		CHECK_NEAR(along[k], p[k].internode, 0.01 * p[k].internode);
		free(l);
		free(a);
		vine_finish(&v);
	}
	CHECK_NEAR(along[1] / along[0], 100.0 / 60.0, 0.01 * 100.0 / 60.0);
	CHECK_NEAR(chord[1] / chord[0], 100.0 / 60.0, 0.01 * 100.0 / 60.0);
	printf("4.5(b) ratios: along the stem %.5f, straight %.5f (100 / 60 = %.5f)\n",
	       along[1] / along[0], chord[1] / chord[0], 100.0 / 60.0);
}

/* The largest |distance - r| of a stem ring's vertex from its smoothed axis point. */
static double ring_error(const struct vine *v, double *mean)
{
	struct mesh stem, leaves;
	size_t at = 0, M = (size_t)v->p.ring_sides, count = 0;
	double worst = 0, sum = 0;

	mesh_init(&stem);
	mesh_init(&leaves);
	CHECK_INT(vine_mesh_append(v, &stem, &leaves), 0);
	for (size_t k = 0; k < v->nshoots; k++) {
		size_t n = v->shoots[k].n;
		struct vec3 *a;

		if (n < 2)
			continue;
		CHECK_INT(vine_smooth(v, k, &a), 0);
		for (size_t i = 0; i < n; i++)
			for (size_t j = 0; j < M; j++) {
				const float *q = stem.positions + 3 * (at + i * M + j);
				double dist = vec3_dist(vec3(q[0], q[1], q[2]), a[i]);

				worst = fmax(worst, fabs(dist - v->p.radius));
				sum += dist;
				count++;
			}
		at += M * (n + 1) + 1;
		free(a);
	}
	CHECK_INT(at, stem.nvertices);
	*mean = sum / (double)count;
	mesh_finish(&stem);
	mesh_finish(&leaves);
	return worst;
}

/* Fig. 4.5(c): radius 2 -> 4 mm. The tube's rings r from the axis; the helix's radius
 * R + r, 2 mm wider; its pitch 2 pi (R + r) / tan theta_p wider with it. */
static void test_radius(const struct vine_support *s)
{
	struct vine_params p[2] = { base(), base() };
	struct helix h[2];
	double ring[2];

	p[1].radius = 0.004;
	for (int k = 0; k < 2; k++) {
		struct vine v;
		double worst;

		grow(&v, &p[k], s, beside());
		h[k] = helix_of(&v);
		worst = ring_error(&v, &ring[k]);
		printf("4.5(c) radius %.3f m: rings %.7f m from the axis (off by %.1e at most), "
		       "helix radius %.5f m (R + r = %.3f), pitch %.4f m\n", p[k].radius, ring[k],
		       worst, h[k].radius_mean, R + p[k].radius, h[k].pitch);
		CHECK(worst < 1e-6);
		vine_finish(&v);
	}
	CHECK_NEAR(ring[1] / ring[0], 2, 1e-4);
	/* the helix wider by the radius's change, to 2 % of it */
	CHECK_NEAR(h[1].radius_mean - h[0].radius_mean, 0.002, 0.02 * 0.002);
	CHECK_NEAR(h[1].pitch / h[0].pitch, (R + 0.004) / (R + 0.002), 0.01);
	printf("4.5(c) helix radius +%.5f m (radius +0.002), pitch ratio %.4f (24 / 22 = %.4f)\n",
	       h[1].radius_mean - h[0].radius_mean, h[1].pitch / h[0].pitch, 24.0 / 22.0);
}

/* Fig. 4.5(d): twining left -> right. The other handedness: the helix turns the other
 * way, by as much, and the whole vine is the base's mirror image in the plane z = 0
 * (the pole and the planting point are symmetric in it). */
static void test_twining(const struct vine_support *s)
{
	struct vine_params p[2] = { base(), base() };
	struct vine v[2];
	struct helix h[2];
	double worst = 0;

	p[1].twining = VINE_RIGHT;
	for (int k = 0; k < 2; k++) {
		grow(&v[k], &p[k], s, beside());
		h[k] = helix_of(&v[k]);
	}
	CHECK(h[0].turned < -3 * VEC_PI && h[1].turned > 3 * VEC_PI);
	CHECK_NEAR(h[1].turned, -h[0].turned, 1e-6);
	CHECK_NEAR(h[1].pitch, h[0].pitch, 1e-6);
	CHECK_INT(v[1].nshoots, v[0].nshoots);
	for (size_t k = 0; k < v[0].nshoots; k++) {
		const struct vine_shoot *a = &v[0].shoots[k], *b = &v[1].shoots[k];

		CHECK_INT(b->n, a->n);
		for (size_t i = 0; i < a->n; i++) {
			struct vec3 m = vec3(a->axis[i].x, a->axis[i].y, -a->axis[i].z);

			worst = fmax(worst, vec3_dist(b->axis[i], m));
		}
	}
	printf("4.5(d) left turns %.3f rad, right %.3f rad; right = left mirrored to %.1e m\n",
	       h[0].turned, h[1].turned, worst);
	CHECK(worst < 1e-9);
	vine_finish(&v[0]);
	vine_finish(&v[1]);
}

/* Whether the main apex, planted `gap` from the pole's side, touches it. */
static bool catches(struct vine_params p, const struct vine_support *s, double gap)
{
	struct vine v;
	bool touched = false;

	p.internodes = p.free_nodes + 3; /* the main axis's circling and a little */
	grow(&v, &p, s, vec3(R + gap, 0, 0));
	for (size_t i = 0; i < v.shoots[0].n; i++)
		touched = touched || v.shoots[0].contact[i];
	vine_finish(&v);
	return touched;
}

/*
 * Fig. 4.5(e): step_time 10 -> 5, the sweep omega the same: the apex turns omega t = 11.25
 * degrees a new point instead of 22.5, so when it has come round to a given side its rod
 * is twice as many points long and reaches twice as far. Planted on the +x side, the rod
 * starts pointing away from the pole and first faces it half a turn later, pi / (omega t)
 * points on: 8 at t = 10, and the next point (laid along the rod before the sweep goes
 * on) makes the rod 9 points long there; 16 at t = 5, the whole rod (2d), after which it
 * stops (nothing touched for 2 internodes). The farthest gap it catches is that rod's
 * reach and r: n (l/d) sin theta_p + r, 22.86 mm and 39.08 mm. Planted 15 mm off, both
 * catch the pole, t = 5 higher and farther from the root. The helix is the same.
 */
static void test_step_time(const struct vine_support *s)
{
	struct vine_params p[2] = { base(), base() };
	const double face[2] = { 9, 16 };
	double reach[2];
	size_t first[2];
	double y[2], out[2];
	struct helix h[2];

	p[1].step_time = 5;
	for (int k = 0; k < 2; k++) {
		double lo = 0.005, hi = 0.1, want;
		size_t d = (size_t)p[k].points_per_internode;
		struct vine v;
		const struct vine_shoot *sh;

		/* the farthest gap caught, bisected to 1e-9 m */
		CHECK(catches(p[k], s, lo) && !catches(p[k], s, hi));
		while (hi - lo > 1e-9) {
			double mid = 0.5 * (lo + hi);

			if (catches(p[k], s, mid))
				lo = mid;
			else
				hi = mid;
		}
		reach[k] = lo;
		want = face[k] * p[k].internode / (double)d * sin(p[k].angle * DEG) + p[k].radius;
		CHECK_NEAR(face[k], fmin(180 / (p[k].sweep * p[k].step_time) + 1, 2 * (double)d), 0);
		CHECK_NEAR(reach[k], want, 1e-8);

		/* planted 15 mm off: where it first touches */
		grow(&v, &p[k], s, beside());
		sh = &v.shoots[0];
		first[k] = 0;
		while (first[k] < sh->n && !sh->contact[first[k]])
			first[k]++;
		CHECK(first[k] < sh->n);
		y[k] = sh->axis[first[k]].y;
		out[k] = hypot(sh->axis[first[k]].x - sh->axis[0].x, sh->axis[first[k]].z - sh->axis[0].z);
		h[k] = helix_of(&v);
		printf("4.5(e) step_time %g (%.2f degrees a point): catches a pole up to %.6f m away "
		       "(%g (l/d) sin theta_p + r = %.6f); planted %.3f m off, first touches at point "
		       "%zu, %.4f m up, %.4f m out from the root; pitch %.4f m\n", p[k].step_time,
		       p[k].sweep * p[k].step_time, reach[k], face[k], want, GAP, first[k], y[k],
		       out[k], h[k].pitch);
		vine_finish(&v);
	}
	/* a pole 30 mm away: caught at t = 5 only */
	CHECK(!catches(p[0], s, 0.030) && catches(p[1], s, 0.030));
	CHECK(first[1] >= first[0] + 4);
	CHECK(y[1] > y[0] + 0.03 && out[1] > 1.5 * out[0]);
	CHECK_NEAR(h[1].pitch / h[0].pitch, 1, 0.01);
}

/* The largest horizontal distance of any raw point from the vertical through v's plant. */
static double spread(const struct vine *v)
{
	double m = 0;

	for (size_t k = 0; k < v->nshoots; k++)
		for (size_t i = 0; i < v->shoots[k].n; i++)
			m = fmax(m, hypot(v->shoots[k].axis[i].x - v->plant.x,
					  v->shoots[k].axis[i].z - v->plant.z));
	return m;
}

/*
 * Fig. 4.5(f): angle 18 -> 30 degrees. With nothing to climb, every shoot circles free:
 * the azimuths are the same at any lean, so every horizontal offset grows by
 * sin 30 / sin 18 and the main apex's rod reaches 2 l sin theta_p. On the pole the turns
 * come closer: the pitch 2 pi (R + r) / tan theta_p, by tan 18 / tan 30.
 */
static void test_angle(const struct vine_support *s)
{
	struct vine_params p[2] = { base(), base() };
	double wide[2], tip[2];
	struct helix h[2];

	p[1].angle = 30;
	for (int k = 0; k < 2; k++) {
		struct vine v;
		const struct vine_shoot *m;
		double want = 2 * VEC_PI * (R + p[k].radius) / tan(p[k].angle * DEG);

		grow(&v, &p[k], NULL, vec3(0.3, 0, -0.2));
		m = &v.shoots[0];
		CHECK_INT(m->n - 1, (p[k].free_nodes + 2) * p[k].points_per_internode);
		wide[k] = spread(&v);
		tip[k] = hypot(m->axis[m->n - 1].x - v.plant.x, m->axis[m->n - 1].z - v.plant.z);
		CHECK_NEAR(tip[k], 2 * p[k].internode * sin(p[k].angle * DEG), 1e-12);
		vine_finish(&v);

		grow(&v, &p[k], s, beside());
		h[k] = helix_of(&v);
		printf("4.5(f) angle %g: free, the vine %.5f m wide of its root (the main rod's "
		       "tip %.5f m); on the pole, pitch %.4f m (2 pi (R + r) / tan theta_p = %.4f)\n",
		       p[k].angle, wide[k], tip[k], h[k].pitch, want);
		CHECK_NEAR(h[k].pitch, want, 0.01 * want);
		vine_finish(&v);
	}
	CHECK_NEAR(wide[1] / wide[0], sin(30 * DEG) / sin(18 * DEG), 1e-9);
	CHECK_NEAR(h[1].pitch / h[0].pitch, tan(18 * DEG) / tan(30 * DEG),
		   0.05 * tan(18 * DEG) / tan(30 * DEG));
	printf("4.5(f) spread ratio %.9f (sin 30 / sin 18 = %.9f), pitch ratio %.4f "
	       "(tan 18 / tan 30 = %.4f)\n", wide[1] / wide[0], sin(30 * DEG) / sin(18 * DEG),
	       h[1].pitch / h[0].pitch, tan(18 * DEG) / tan(30 * DEG));
}

/* Fig. 4.5(g): free_nodes 1 -> 2. The main axis straight up U l from its root (points
 * 0 .. U d above it, the next leaning theta_p), drawn bent over U d - 1 points; the
 * first bud at node U + 1. */
static void test_free_nodes(const struct vine_support *s)
{
	struct vine_params p[2] = { base(), base() };

	p[1].free_nodes = 2;
	for (int k = 0; k < 2; k++) {
		struct vine v;
		const struct vine_shoot *m;
		size_t d = (size_t)p[k].points_per_internode, u = (size_t)p[k].free_nodes * d;
		size_t bent = 0, lean = 0;
		struct vec3 *a, e;

		grow(&v, &p[k], s, beside());
		m = &v.shoots[0];
		CHECK_INT(m->free_until, u);
		for (size_t i = 0; i <= u; i++)
			CHECK(m->axis[i].x == v.plant.x && m->axis[i].z == v.plant.z);
		while (lean < m->n && m->axis[lean + 1].x == v.plant.x &&
		       m->axis[lean + 1].z == v.plant.z)
			lean++;
		CHECK_INT(lean, u);
		e = vec3_sub(m->axis[u + 1], m->axis[u]);
		CHECK_NEAR(acos(e.y / vec3_len(e)) / DEG, p[k].angle, 1e-9);
		CHECK_NEAR(m->axis[u].y - v.plant.y, p[k].free_nodes * p[k].internode, 1e-12);
		CHECK_INT(vine_smooth(&v, 0, &a), 0);
		for (size_t i = 1; i < u; i++)
			bent += a[i].x != m->axis[i].x || a[i].z != m->axis[i].z;
		CHECK(vec3_dist(a[u], m->axis[u]) == 0);
		CHECK_INT(bent, u - 1);
		CHECK(v.nshoots >= 2);
		CHECK_INT(v.shoots[1].node, p[k].free_nodes + 1);
		helix_of(&v);
		printf("4.5(g) free_nodes %d: straight %.4f m (U l = %.4f), then leaning from point "
		       "%zu; %zu points drawn bent; the first bud at node %d\n", p[k].free_nodes,
		       m->axis[u].y - v.plant.y, p[k].free_nodes * p[k].internode, lean, bent,
		       v.shoots[1].node);
		free(a);
		vine_finish(&v);
	}
}

/* Nodes, every shoot's, and buds (each lateral took a leaf at a node of the main axis). */
static void nodes_and_buds(const struct vine *v, size_t *nodes, size_t *buds)
{
	*nodes = 0;
	for (size_t k = 0; k < v->nshoots; k++)
		*nodes += vine_shoot_nodes(v, k);
	*buds = v->nshoots - 1;
}

/* The same leaf, field by field (the struct has padding), its corners bit for bit. */
static bool same_leaf(const struct vine_leaf *a, const struct vine_leaf *b)
{
	if (a->shoot != b->shoot || a->node != b->node || a->cotyledon != b->cotyledon)
		return false;
	for (int c = 0; c < 4; c++)
		if (vec3_dist(a->p[c], b->p[c]) != 0)
			return false;
	return true;
}

/* A leaf's outward direction (its node to the far corner), unit. */
static struct vec3 outward(const struct vine_leaf *l)
{
	return vec3_norm_or(vec3_sub(l->p[2], l->p[0]), vec3(0, 0, 0));
}

/* Both stems' meshes, the same bytes; *leaf_vertices a's leaves' vertices. */
static bool same_stems(const struct vine *a, const struct vine *b, size_t *leaf_vertices)
{
	struct mesh sa, sb, la, lb;
	bool same;

	mesh_init(&sa);
	mesh_init(&sb);
	mesh_init(&la);
	mesh_init(&lb);
	CHECK_INT(vine_mesh_append(a, &sa, &la), 0);
	CHECK_INT(vine_mesh_append(b, &sb, &lb), 0);
	same = sa.nvertices == sb.nvertices && sa.nindices == sb.nindices &&
	       memcmp(sa.positions, sb.positions, 3 * sa.nvertices * sizeof(float)) == 0 &&
	       memcmp(sa.indices, sb.indices, sa.nindices * sizeof(*sa.indices)) == 0;
	*leaf_vertices = la.nvertices; /* a's */
	mesh_finish(&sa);
	mesh_finish(&sb);
	mesh_finish(&la);
	mesh_finish(&lb);
	return same;
}

/*
 * Fig. 4.6: the model's parameters. The growth and the stems the base's, bit for bit;
 * (b) cotyledons 0 and leaves 0: no leaf at all; (c) cotyledons 2: an opposite pair at
 * node 1, one leaf more, the others the base's; (d) two leaves a node: opposite pairs,
 * 2 (nodes - 1) - buds leaves besides the cotyledon where the base has nodes - 1 - buds;
 * (f) leaf size 25: the same leaves scaled by 25 / 12 about their nodes, diagonals 2 gamma.
 */
static void test_model(const struct vine_support *s)
{
	struct vine_params p = base();
	struct vine b, v;
	struct vine_leaf *bl, *l;
	size_t nb, n, nodes, buds, lv, pairs = 0;

	grow(&b, &p, s, beside());
	nb = leaves_of(&b, &bl);
	nodes_and_buds(&b, &nodes, &buds);
	CHECK(buds >= 2);
	/* the base: one cotyledon at node 1, a leaf at every other node but the buds' */
	CHECK_INT(nb, 1 + (nodes - 1) - buds);
	CHECK(bl[0].cotyledon && bl[0].shoot == 0 && bl[0].node == 1 && !bl[1].cotyledon);
	for (size_t i = 0; i < nb; i++)
		CHECK_NEAR(vec3_dist(bl[i].p[0], bl[i].p[2]), 2 * p.leaf_size, 1e-9);
	printf("4.6(a) base: %zu shoots, %zu nodes, %zu buds, %zu leaves (1 cotyledon)\n",
	       b.nshoots, nodes, buds, nb);

	/* (b) woody: nothing */
	p = base();
	p.cotyledons = 0;
	p.leaves_per_node = 0;
	grow(&v, &p, s, beside());
	CHECK(same_growth(&v, &b));
	CHECK(same_stems(&v, &b, &lv));
	n = leaves_of(&v, &l);
	CHECK_INT(n, 0);
	CHECK_INT(lv, 0);
	printf("4.6(b) no cotyledons nor leaves: %zu leaves, %zu leaf vertices\n", n, lv);
	free(l);
	vine_finish(&v);

	/* (c) dicotyledon: two cotyledons, opposite, the rest as the base's */
	p = base();
	p.cotyledons = 2;
	grow(&v, &p, s, beside());
	CHECK(same_growth(&v, &b));
	CHECK(same_stems(&v, &b, &lv));
	n = leaves_of(&v, &l);
	CHECK_INT(n, nb + 1);
	CHECK(l[0].cotyledon && l[1].cotyledon && !l[2].cotyledon);
	CHECK(l[0].shoot == 0 && l[0].node == 1 && l[1].shoot == 0 && l[1].node == 1);
	CHECK_NEAR(vec3_dot(outward(&l[0]), outward(&l[1])), -1, 1e-12);
	for (size_t i = 1; i < nb; i++)
		CHECK(same_leaf(&l[i + 1], &bl[i]));
	printf("4.6(c) two cotyledons: %zu leaves (the base's %zu and one), the pair's "
	       "directions' dot product %.12f\n", n, nb, vec3_dot(outward(&l[0]), outward(&l[1])));
	free(l);
	vine_finish(&v);

	/* (d) two leaves a node: opposite pairs */
	p = base();
	p.leaves_per_node = 2;
	grow(&v, &p, s, beside());
	CHECK(same_growth(&v, &b));
	n = leaves_of(&v, &l);
	CHECK_INT(n, 1 + 2 * (nodes - 1) - buds);
	for (size_t i = 1; i + 1 < n; i++) {
		if (l[i].shoot != l[i + 1].shoot || l[i].node != l[i + 1].node)
			continue;
		CHECK_NEAR(vec3_dot(outward(&l[i]), outward(&l[i + 1])), -1, 1e-12);
		CHECK(vec3_dist(l[i].p[0], l[i + 1].p[0]) == 0);
		pairs++;
	}
	CHECK_INT(pairs, nodes - 1 - buds);
	printf("4.6(d) two leaves a node: %zu leaves (%zu opposite pairs, %zu single at the "
	       "buds' nodes, the cotyledon) against the base's %zu\n", n, pairs, buds, nb);
	free(l);
	vine_finish(&v);

	/* (f) leaf size 12 -> 25 mm */
	p = base();
	p.leaf_size = 0.025;
	grow(&v, &p, s, beside());
	CHECK(same_growth(&v, &b));
	n = leaves_of(&v, &l);
	CHECK_INT(n, nb);
	for (size_t i = 0; i < n; i++) {
		CHECK(l[i].shoot == bl[i].shoot && l[i].node == bl[i].node);
		CHECK(vec3_dist(l[i].p[0], bl[i].p[0]) == 0);
		CHECK_NEAR(vec3_dist(l[i].p[0], l[i].p[2]), 2 * 0.025, 1e-9);
		CHECK_NEAR(vec3_dist(l[i].p[1], l[i].p[3]), 2 * 0.025, 1e-9);
		for (int c = 1; c < 4; c++)
			CHECK(vec3_dist(vec3_sub(l[i].p[c], l[i].p[0]),
					vec3_scale(vec3_sub(bl[i].p[c], bl[i].p[0]), 25.0 / 12.0)) < 1e-12);
	}
	printf("4.6(f) leaf size 0.025 m: %zu leaves, diagonals %.9f m (the base's %.9f)\n", n,
	       vec3_dist(l[0].p[0], l[0].p[2]), vec3_dist(bl[0].p[0], bl[0].p[2]));
	free(l);
	vine_finish(&v);

	free(bl);
	vine_finish(&b);
}

int main(void)
{
	struct vine_support *s = pole(R, H, 64);

	test_internode(s);
	test_radius(s);
	test_twining(s);
	test_step_time(s);
	test_angle(s);
	test_free_nodes(s);
	test_model(s);
	vine_support_destroy(s);
	printf("ok\n");
	return 0;
}
