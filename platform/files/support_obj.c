/* SPDX-License-Identifier: MIT */
/*
 * A vine's support from a Wavefront OBJ file, read by assimp (Debian's libassimp): a
 * well-kept parser rather than one more of our own for a format with many dialects.
 */
#include "support_obj.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

/* The triangles (3-index faces) of mesh m: Triangulate leaves points and lines as such. */
static size_t mesh_triangles(const struct aiMesh *m)
{
	size_t n = 0;

	for (unsigned f = 0; f < m->mNumFaces; f++)
		n += m->mFaces[f].mNumIndices == 3;
	return n;
}

/* Counts the vertices and triangles the node tree places (a mesh used twice counts twice),
 * stopping past the limit so that a hostile file's count cannot overflow. */
static void count(const struct aiScene *sc, const struct aiNode *node, size_t *nv, size_t *nt)
{
	for (unsigned i = 0; i < node->mNumMeshes && *nt <= SUPPORT_OBJ_MAX_TRIANGLES; i++) {
		const struct aiMesh *m = sc->mMeshes[node->mMeshes[i]];
		size_t t = mesh_triangles(m);

		if (t) {
			*nv += m->mNumVertices;
			*nt += t;
		}
	}
	for (unsigned i = 0; i < node->mNumChildren && *nt <= SUPPORT_OBJ_MAX_TRIANGLES; i++)
		count(sc, node->mChildren[i], nv, nt);
}

/* Appends the node's meshes under transform xf (the product of its ancestors') and its
 * children's. false at a non-finite coordinate. */
static bool collect(const struct aiScene *sc, const struct aiNode *node, struct aiMatrix4x4 xf,
		    struct support_obj *s)
{
	aiMultiplyMatrix4(&xf, &node->mTransformation);
	for (unsigned i = 0; i < node->mNumMeshes; i++) {
		const struct aiMesh *m = sc->mMeshes[node->mMeshes[i]];
		uint32_t base = (uint32_t)s->nvertices;

		if (!mesh_triangles(m))
			continue;
		for (unsigned v = 0; v < m->mNumVertices; v++) {
			struct aiVector3D p = m->mVertices[v];
			float *out = s->positions + 3 * s->nvertices++;

			aiTransformVecByMatrix4(&p, &xf);
			out[0] = p.x;
			out[1] = p.y;
			out[2] = p.z;
			if (!isfinite(out[0]) || !isfinite(out[1]) || !isfinite(out[2]))
				return false;
		}
		for (unsigned f = 0; f < m->mNumFaces; f++) {
			const struct aiFace *face = &m->mFaces[f];

			if (face->mNumIndices != 3)
				continue;
			for (int k = 0; k < 3; k++)
				s->indices[3 * s->ntriangles + (size_t)k] = base + face->mIndices[k];
			s->ntriangles++;
		}
	}
	for (unsigned i = 0; i < node->mNumChildren; i++)
		if (!collect(sc, node->mChildren[i], xf, s))
			return false;
	return true;
}

/* assimp picks its importer by the name's extension first: a support is an OBJ, so the
 * name must say so, or a .ply or a .stl would be read as one. */
static bool obj_name(const char *path)
{
	size_t n = strlen(path);

	return n >= 4 && strcasecmp(path + n - 4, ".obj") == 0;
}

int support_obj_read(const char *path, struct support_obj *s, struct error *err)
{
	const struct aiScene *sc;
	struct aiMatrix4x4 id;
	struct stat st;
	size_t nv = 0, nt = 0;
	int ret = 0;

	memset(s, 0, sizeof(*s));
	if (stat(path, &st) < 0)
		return error_at(err, -EINVAL, path, 0, "%s", strerror(errno));
	if (!S_ISREG(st.st_mode))
		return error_at(err, -EINVAL, path, 0, "not a regular file");
	if (!obj_name(path))
		return error_at(err, -EINVAL, path, 0, "not a Wavefront OBJ file (its name does "
				"not end in .obj)");
	sc = aiImportFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
	if (!sc) {
		const char *why = aiGetErrorString();

		return error_at(err, -EINVAL, path, 0, "not an OBJ file assimp can read: %s",
				why && why[0] ? why : "no reason given");
	}
	if (sc->mRootNode)
		count(sc, sc->mRootNode, &nv, &nt);
	if (nt == 0) {
		ret = error_at(err, -EINVAL, path, 0, "no triangles");
	} else if (nt > SUPPORT_OBJ_MAX_TRIANGLES) {
		ret = error_at(err, -EINVAL, path, 0, "more than %u triangles",
			       SUPPORT_OBJ_MAX_TRIANGLES);
	} else {
		s->positions = malloc(3 * nv * sizeof(*s->positions));
		s->indices = malloc(3 * nt * sizeof(*s->indices));
		aiIdentityMatrix4(&id);
		if (!s->positions || !s->indices)
			ret = -ENOMEM;
		else if (!collect(sc, sc->mRootNode, id, s))
			ret = error_at(err, -EINVAL, path, 0, "a vertex with a coordinate that is "
				       "not a finite number");
	}
	aiReleaseImport(sc);
	if (ret < 0)
		support_obj_finish(s);
	return ret;
}

void support_obj_finish(struct support_obj *s)
{
	free(s->positions);
	free(s->indices);
	memset(s, 0, sizeof(*s));
}
