/* SPDX-License-Identifier: MIT */
/*
 * Opening an origami leaf from the bud (t = 0) to flat (t = 1), rigidly: every face keeps
 * its shape and turns only about its creases (seed 003, Fig. 6; docs/origami-leaves.md).
 *
 * Fold angles (0 flat, pi folded flat) follow the opening: the creases from O fold by
 * pi (1 - t); at a fork the children follow their parent by the degree-4 vertex's
 * relation tan(rho_parent / 2) = k tan(rho_child / 2), k = cos((a + b) / 2) / cos((a -
 * b) / 2), and the extra mountain by rho_parent; at a node of the midrib the side veins
 * fold as the midrib entering it, and the extra mountains and the midrib leaving it are
 * solved from the node's closure (the rotations about its six creases compose to the
 * identity), by Newton's method continued from t = 0 where all are pi.
 */
#include <errno.h>
#include <math.h>
#include <string.h>

#include "ori.h"
#include "vec.h"

struct rigid {
	double r[3][3], t[3];
};

static void rot_matrix(const double u[3], double th, double r[3][3])
{
	double c = cos(th), s = sin(th), k = 1 - c;

	r[0][0] = c + u[0] * u[0] * k;
	r[0][1] = u[0] * u[1] * k - u[2] * s;
	r[0][2] = u[0] * u[2] * k + u[1] * s;
	r[1][0] = u[1] * u[0] * k + u[2] * s;
	r[1][1] = c + u[1] * u[1] * k;
	r[1][2] = u[1] * u[2] * k - u[0] * s;
	r[2][0] = u[2] * u[0] * k - u[1] * s;
	r[2][1] = u[2] * u[1] * k + u[0] * s;
	r[2][2] = c + u[2] * u[2] * k;
}

static void mat_mul(const double a[3][3], const double b[3][3], double out[3][3])
{
	double r[3][3];

	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
	memcpy(out, r, sizeof(r));
}

/* a o b: b first. */
static struct rigid rigid_mul(const struct rigid *a, const struct rigid *b)
{
	struct rigid r;

	mat_mul(a->r, b->r, r.r);
	for (int i = 0; i < 3; i++)
		r.t[i] = a->r[i][0] * b->t[0] + a->r[i][1] * b->t[1] + a->r[i][2] * b->t[2] +
			 a->t[i];
	return r;
}

/* The rotation by th about the line through p (z = 0) along the unit u (z = 0). */
static struct rigid rigid_about(const double p[2], const double u[2], double th)
{
	double axis[3] = { u[0], u[1], 0 };
	struct rigid r;

	rot_matrix(axis, th, r.r);
	for (int i = 0; i < 3; i++)
		r.t[i] = -(r.r[i][0] * p[0] + r.r[i][1] * p[1]) + (i < 2 ? p[i] : 0);
	return r;
}

/* The rotation by th about crease c (flat). */
static struct rigid rigid_crease(const struct ori_leaf *l, const struct ori_crease *c, double th)
{
	const double *a = l->flat[c->a], *b = l->flat[c->b];
	double u[2] = { b[0] - a[0], b[1] - a[1] }, n = hypot(u[0], u[1]);

	u[0] /= n;
	u[1] /= n;
	return rigid_about(a, u, th);
}

/* The node's closure: the rotations about its creases, counter-clockwise from the midrib
 * leaving it, minus the identity. x = {rho_mountain, rho_out}. */
static void node_residual(double phi, double psi, double rho_in, const double x[2],
			  double res[9])
{
	const double a[6] = { VEC_PI / 2, VEC_PI / 2 + psi, VEC_PI / 2 + phi,
			      3 * VEC_PI / 2, 5 * VEC_PI / 2 - phi, 5 * VEC_PI / 2 - psi };
	const double f[6] = { x[1], -x[0], rho_in, rho_in, rho_in, -x[0] };
	double r[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, q[3][3];

	for (int i = 0; i < 6; i++) {
		double u[3] = { cos(a[i]), sin(a[i]), 0 };

		rot_matrix(u, f[i], q);
		mat_mul(r, q, r);
	}
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			res[3 * i + j] = r[i][j] - (i == j);
}

static double norm9(const double r[9])
{
	double s = 0;

	for (int i = 0; i < 9; i++)
		s += r[i] * r[i];
	return sqrt(s);
}

/* Newton (Gauss-Newton on the nine residuals) from x. */
static int node_solve(double phi, double psi, double rho_in, double x[2])
{
	if (rho_in == 0) { /* flat: the one solution, where Newton would crawl */
		x[0] = x[1] = 0;
		return 0;
	}
	for (int it = 0; it < 40; it++) {
		double r[9], j[9][2], h = 1e-7, a = 0, b = 0, c = 0, g0 = 0, g1 = 0, det, dx0, dx1;

		node_residual(phi, psi, rho_in, x, r);
		if (norm9(r) < 1e-13)
			return 0;
		for (int k = 0; k < 2; k++) {
			double xh[2] = { x[0], x[1] }, rh[9];

			xh[k] += h;
			node_residual(phi, psi, rho_in, xh, rh);
			for (int i = 0; i < 9; i++)
				j[i][k] = (rh[i] - r[i]) / h;
		}
		for (int i = 0; i < 9; i++) {
			a += j[i][0] * j[i][0];
			b += j[i][0] * j[i][1];
			c += j[i][1] * j[i][1];
			g0 += j[i][0] * r[i];
			g1 += j[i][1] * r[i];
		}
		/* a touch of damping: the Jacobian is singular where the leaf lies flat */
		a += 1e-12;
		c += 1e-12;
		det = a * c - b * b;
		if (!(fabs(det) > 0))
			return -EDOM;
		dx0 = -(c * g0 - b * g1) / det;
		dx1 = -(a * g1 - b * g0) / det;
		x[0] += dx0;
		x[1] += dx1;
		if (fabs(dx0) + fabs(dx1) < 1e-15)
			break;
	}
	{
		double r[9];

		node_residual(phi, psi, rho_in, x, r);
		return norm9(r) < 1e-9 ? 0 : -EDOM;
	}
}

/* Every crease's fold angle at t (0 flat, pi folded); node angles solved in order along
 * the midrib from the x they had at the previous t (prev: nnodes pairs). */
static int fold_angles(const struct ori_leaf *l, double t, double *rho, double (*x)[2])
{
	for (size_t c = 0; c < l->ncreases; c++) {
		const struct ori_crease *k = &l->creases[c];
		double p = k->parent >= 0 ? rho[k->parent] : 0;

		switch (k->rule) {
		case ORI_RULE_BASE:
			rho[c] = VEC_PI * (1 - t);
			break;
		case ORI_RULE_FORK_CHILD:
			rho[c] = 2 * atan2(sin(p / 2), k->k * cos(p / 2));
			break;
		case ORI_RULE_FORK_MOUNTAIN:
		case ORI_RULE_NODE_VEIN:
			rho[c] = p;
			break;
		case ORI_RULE_NODE_MOUNTAIN:
		case ORI_RULE_NODE_MIDRIB: {
			/* creases are made along the midrib in order: its node is solved by now */
			const struct ori_node_geo *g = &l->nodes[k->node];
			double *xn = x[k->node];

			if (c == (size_t)g->mountain[0]) {
				int ret = node_solve(g->phi, g->psi, rho[g->in], xn);

				if (ret < 0)
					return ret;
			}
			rho[c] = k->rule == ORI_RULE_NODE_MOUNTAIN ? xn[0] : xn[1];
			break;
		}
		}
	}
	return 0;
}

/* Fold angles continued from t0 (its node solutions in x) to t1, in steps of about 0.01:
 * the nodes' solutions followed from the bud. */
static int fold_angles_to(const struct ori_leaf *l, double t0, double t1, double *rho,
			  double (*x)[2])
{
	int steps = l->nnodes ? 1 + (int)ceil(fabs(t1 - t0) * 96) : 1;

	for (int s = 1; s <= steps; s++) {
		int ret = fold_angles(l, t0 + (t1 - t0) * s / steps, rho, x);

		if (ret < 0)
			return ret;
	}
	return 0;
}

/* The faces placed at fold angles rho (the midrib's base fold is pi (1 - t)). */
static int place(const struct ori_leaf *l, double t, const double *rho, double (*out)[3])
{
	static const double o[2] = { 0, 0 }, up[2] = { 0, 1 };
	struct rigid tf[512], g;
	bool set[1024];

	memset(&tf[l->root_face], 0, sizeof(tf[0]));
	for (int i = 0; i < 3; i++)
		tf[l->root_face].r[i][i] = 1;
	/* the walk crossed each ray from the face on its right to the one on its left */
	for (size_t f = (size_t)l->root_face + 1; f < l->nfaces; f++) {
		const struct ori_crease *c = &l->creases[l->face_across[f]];
		double r = c->type == ORI_VALLEY ? rho[l->face_across[f]] : -rho[l->face_across[f]];
		struct rigid m = rigid_crease(l, c, r);

		tf[f] = rigid_mul(&tf[f - 1], &m);
	}
	for (size_t f = (size_t)l->root_face; f-- > 0;) {
		const struct ori_crease *c = &l->creases[l->face_across[f + 1]];
		double r = c->type == ORI_VALLEY ? rho[l->face_across[f + 1]] :
						   -rho[l->face_across[f + 1]];
		struct rigid m = rigid_crease(l, c, -r);

		tf[f] = rigid_mul(&tf[f + 1], &m);
	}
	/* symmetric about x = 0: the root face (right of the midrib) turned back by half the
	 * midrib's fold, so both halves rise alike */
	g = rigid_about(o, up, -VEC_PI * (1 - t) / 2);
	memset(set, 0, sizeof(set));
	for (size_t f = 0; f < l->nfaces; f++) {
		struct rigid m = rigid_mul(&g, &tf[f]);

		for (size_t k = 0; k < l->face_len[f]; k++) {
			int v = l->face_index[l->face_start[f] + k];
			const double *p = l->flat[v];

			if (set[v])
				continue;
			for (int i = 0; i < 3; i++)
				out[v][i] = m.r[i][0] * p[0] + m.r[i][1] * p[1] + m.t[i];
			set[v] = true;
		}
	}
	return 0;
}

static bool fits(const struct ori_leaf *l)
{
	return l->ncreases <= 1024 && l->nfaces <= 512 && l->nvertices <= 1024 && l->root_face >= 0 &&
	       l->nnodes <= ORI_MAX_LEAF_NODES;
}

static void start(double (*x)[2])
{
	for (size_t i = 0; i < ORI_MAX_LEAF_NODES; i++)
		x[i][0] = x[i][1] = VEC_PI;
}

int ori_open(const struct ori_leaf *l, double t, double (*out)[3])
{
	double rho[1024], x[ORI_MAX_LEAF_NODES][2];
	int ret;

	if (!fits(l))
		return -EINVAL;
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	start(x);
	if ((ret = fold_angles_to(l, 0, t, rho, x)) < 0)
		return ret;
	return place(l, t, rho, out);
}

int ori_open_frames(const struct ori_leaf *l, size_t n, double (*out)[3])
{
	double rho[1024], x[ORI_MAX_LEAF_NODES][2], t0 = 0;
	int ret;

	if (!fits(l) || n < 2)
		return -EINVAL;
	start(x);
	for (size_t k = 0; k < n; k++) {
		double t = (double)k / (double)(n - 1);

		if ((ret = fold_angles_to(l, t0, t, rho, x)) < 0 ||
		    (ret = place(l, t, rho, out + k * l->nvertices)) < 0)
			return ret;
		t0 = t;
	}
	return 0;
}

int ori_unfold_frames(const struct ori_leaf *l, size_t n, double (*out)[3])
{
	for (size_t j = 0; j < n; j++) {
		double s = (double)j / (double)n;
		bool curl = s > ORI_UNFOLD_OPEN;
		double t = curl ? 1 - (s - ORI_UNFOLD_OPEN) / (1 - ORI_UNFOLD_OPEN) * (1 - l->rest) :
				  s / ORI_UNFOLD_OPEN;
		int ret = ori_open(l, t, out + j * l->nvertices);

		if (ret < 0)
			return ret;
		if (curl)
			for (size_t v = 0; v < l->nvertices; v++)
				out[j * l->nvertices + v][2] = -out[j * l->nvertices + v][2];
	}
	return 0;
}

int ori_rest(const struct ori_leaf *l, double (*out)[3])
{
	int ret = ori_open(l, l->rest, out);

	if (ret < 0)
		return ret;
	for (size_t v = 0; v < l->nvertices; v++)
		out[v][2] = -out[v][2];
	return 0;
}
