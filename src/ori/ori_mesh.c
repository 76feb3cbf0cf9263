/* SPDX-License-Identifier: MIT */
/* An origami leaf as triangles: flat-shaded faces, so the folds show. */
#include <errno.h>
#include <math.h>

#include "mesh_buffer.h"
#include "ori.h"

size_t ori_mesh_triangles(const struct ori_leaf *l)
{
	size_t n = 0;

	for (size_t f = 0; f < l->nfaces; f++)
		n += l->face_len[f] - 2;
	return n;
}

static void moved(const double *xf, const double p[3], double out[3])
{
	for (int i = 0; i < 3; i++)
		out[i] = xf ? xf[4 * i] * p[0] + xf[4 * i + 1] * p[1] + xf[4 * i + 2] * p[2] +
				      xf[4 * i + 3] :
			      p[i];
}

int ori_mesh_append(const struct ori_leaf *l, const double (*pos)[3], const double *xf,
		    struct mesh *m)
{
	size_t nv = 0, ni = 3 * ori_mesh_triangles(l);
	int ret;

	for (size_t f = 0; f < l->nfaces; f++)
		nv += l->face_len[f];
	if ((ret = mesh_reserve(m, nv, ni)) < 0)
		return ret;
	for (size_t f = 0; f < l->nfaces; f++) {
		const int *idx = l->face_index + l->face_start[f];
		size_t n = l->face_len[f], base = m->nvertices;
		double nrm[3] = { 0, 0, 0 }, len;

		/* Newell's normal of the moved face: planar, so any three corners would do,
		 * but this one does not care which are nearly in line */
		for (size_t k = 0; k < n; k++) {
			double p[3], q[3];

			moved(xf, pos[idx[k]], p);
			moved(xf, pos[idx[(k + 1) % n]], q);
			nrm[0] += (p[1] - q[1]) * (p[2] + q[2]);
			nrm[1] += (p[2] - q[2]) * (p[0] + q[0]);
			nrm[2] += (p[0] - q[0]) * (p[1] + q[1]);
		}
		len = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
		for (int i = 0; i < 3; i++)
			nrm[i] = len > 0 ? nrm[i] / len : (i == 2);
		for (size_t k = 0; k < n; k++) {
			double p[3];

			moved(xf, pos[idx[k]], p);
			for (int i = 0; i < 3; i++) {
				m->positions[3 * m->nvertices + (size_t)i] = (float)p[i];
				m->normals[3 * m->nvertices + (size_t)i] = (float)nrm[i];
			}
			m->nvertices++;
		}
		for (size_t k = 1; k + 1 < n; k++) {
			m->indices[m->nindices++] = (uint32_t)base;
			m->indices[m->nindices++] = (uint32_t)(base + k);
			m->indices[m->nindices++] = (uint32_t)(base + k + 1);
		}
	}
	return 0;
}
