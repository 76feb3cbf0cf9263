/* SPDX-License-Identifier: MIT */
/*
 * src/export/ (floor 7 of src/FLOORS): glTF, OBJ and skeleton.json, as bytes in
 * memory. Includes the systems below it, not doc.
 */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "buf.h"
#include "mesh.h"
#include "tree.h"

/*
 * Exporters append to `out` in memory; platform/ puts the bytes into files. All return 0
 * or a negative errno (-ENOMEM; -EFBIG past glTF's 4 GiB; -EINVAL for a bad MTL name) and
 * leave `out` as it was on failure. Same input, same bytes.
 *
 * The meshes are m, made from tree t; mk says where each of t's leaves' part of m's leaves
 * begins (the app keeps it with its mesh, tree_mesh_build_marked), NULL or unknown when
 * there is none. t's season is what the leaves show (season.h): in summer every leaf is the
 * one green and the files are what they were before seasons, byte for byte (the marks are
 * not looked at); in spring and autumn each leaf takes its palette entry
 * (season_leaf_color), all leaves the palette's first entry where mk does not describe m;
 * in winter there are no leaves in the files at all. The bark is the same in every season.
 *
 * t's vines (t->vines) are not in m (the app draws them apart): export_glb and export_obj
 * mesh them from t (vine_mesh_append, export_vines.h) and write them after the tree, the
 * stems in their own "vine" material (MATERIAL_VINE_RGB, one-sided: closed tubes), the
 * leaves in the leaves' material, in summer's green, in spring's and autumn's palette's
 * first entry (mk describes the tree's own leaves only), in winter not at all. A tree
 * without vines has the bytes it had before vines.
 *
 * t's wood (t->wood, wood.h): m leaves out the swept tubes of the branches the wood holds
 * (tree_branch_in_wood), so export_glb and export_obj write the wood's bark (wood->bark,
 * the iso-surface, closed, smooth normals) after m's bark, in the bark's material; the
 * twigs keep their swept tubes in m's bark. A tree without wood has the bytes it had
 * before wood.
 */

/* glTF 2.0 binary: y up, metres, normals, "bark" and double-sided leaves materials; in
 * spring and autumn the leaves' colours are their vertices' COLOR_0 (export_gltf.c). The
 * one mesh's primitives: "bark", "wood" (the wood's bark, in the bark's material), "leaves",
 * "vine" and "vine-leaves" (each left out when it has no triangles), named so in their
 * accessors' names. */
int export_glb(const struct tree *t, const struct tree_mesh *m, const struct tree_mesh_marks *mk,
	       struct buf *out);

/*
 * The wind a model carries home (issue 26, docs/living-trees.md, "The wind in model.glb"):
 * the screen's sway (src/live/) at this strength and angle, the skeleton's phases from
 * this seed (the document's, so a replay exports the same file).
 */
struct export_wind {
	double strength; /* 0..1; 0 (a still screen) exports LIVE_WIND_DEFAULT_STRENGTH, so
			  * every model carries its wind */
	double angle;    /* radians: the wind's direction at t = 0, (cos, 0, sin) */
	uint64_t seed;   /* the document's seed */
	bool floats;     /* the targets as FLOAT deltas, not KHR_mesh_quantization's bytes
			  * (for importers without the extension; 3 times the bytes) */
};
/* The wind's direction an export takes, until the app says otherwise: along +x, across
 * the front view, where the sway shows best. */
#define EXPORT_WIND_ANGLE 0.0
/* The strength an export uses for w: w->strength, or LIVE_WIND_DEFAULT_STRENGTH for 0. */
double export_wind_strength(const struct export_wind *w);
/*
 * export_glb with the tree's sway as a looping animation named "wind" (NULL: export_glb).
 * Every primitive gets LIVE_WIND_TARGETS morph targets (live_wind_targets of its
 * vertices, bound to the skeleton as the renderer binds them: the bark and leaves by mk,
 * the wood's bark and the vines by the nearest skeleton point), as normalised BYTE
 * deltas (KHR_mesh_quantization, each target's scale folded into its animated weight) or
 * floats; the mesh's weights are 0, so the rest pose is export_glb's: its POSITION,
 * NORMAL, COLOR_0 and indices are the same bytes at the same offsets, the BIN chunk
 * begins with export_glb's, and the wind's data follows. One CUBICSPLINE sampler
 * (live_wind_weights_at, live_wind_rates_at as tangents) over the loop T_loop <= 8 s,
 * its first and last keys equal. A tree without branches has no skeleton to sway: its
 * file is export_glb's. 0, -EINVAL (strength outside 0..1, angle not finite), -ENOMEM
 * or -EFBIG.
 */
int export_glb_wind(const struct tree *t, const struct tree_mesh *m,
		    const struct tree_mesh_marks *mk, const struct export_wind *wind,
		    struct buf *out);
/*
 * forest.glb (issue 27, docs/forest.md, "Headless and for the teacher"): every tree of
 * today's forest in one glTF, each a root node named "tree-N" (N its number) translated
 * to its place (metres, y up), with its own mesh: model.glb's primitives, accessor for
 * accessor the same bytes (export_glb_wind's at this wind and the tree's seed), the
 * materials shared (each in the file once). With wind, ONE animation "wind" with a
 * channel (the node's weights) and a CUBICSPLINE sampler a tree with branches, every
 * tree's wind set up over the same loop, loop_s seconds (live_wind_params.loop; the
 * forest's is LIVE_WIND_COMMON_LOOP_S), so every sampler runs over [0, loop_s], its first
 * and last keys equal: the whole animation loops as one. wind->seed is not used: each
 * tree's phases come from its own drawing's seed. A tree without branches: its mesh
 * without targets, no channel; a tree without triangles: its node without a mesh; no
 * tree: an empty scene. wind NULL: a still forest (loop_s not looked at). The trees'
 * order is the nodes'. 0, -EINVAL (a tree or mesh missing, a position not finite, the
 * wind's parameters, loop_s not within LIVE_WIND_COMMON_LOOP_MIN_S ..
 * LIVE_WIND_COMMON_LOOP_MAX_S), -ENOMEM or -EFBIG (out as it was).
 */
struct export_forest_tree {
	const struct tree *tree;
	const struct tree_mesh *mesh;          /* tree_mesh_build's, at full detail */
	const struct tree_mesh_marks *marks;   /* NULL: found again */
	uint64_t seed;                         /* the drawing's */
	uint64_t number;                       /* its number in the day: the node's "tree-N" */
	double position[3];                    /* metres, y up */
};
int export_glb_forest(const struct export_forest_tree *trees, size_t n,
		      const struct export_wind *wind, double loop_s, struct buf *out);
/* The same for one mesh of leaves alone (an origami leaf, ori_mesh_append): the leaves'
 * green, double-sided material, the node and mesh named name. */
int export_glb_leaf(const struct mesh *m, const char *name, struct buf *out);
/* Wavefront OBJ with its MTL; the OBJ refers to the MTL as mtl_name (e.g. "model.mtl").
 * In spring and autumn the leaves' faces are grouped by colour, one material each
 * ("leaves-autumn-3": palette entry 3), and the MTL has the materials used. Objects "bark",
 * "wood" (usemtl bark), "leaves", "vine" and "vine-leaves", each when it has faces. */
int export_obj(const struct tree *t, const struct tree_mesh *m, const struct tree_mesh_marks *mk,
	       const char *mtl_name, struct buf *obj, struct buf *mtl);
/* Renames the MTL an OBJ made by export_obj refers to (its mtllib line), for an OBJ built
 * before its file's name was known. 0, -EINVAL (no mtllib line, a bad name) or -ENOMEM
 * (obj unchanged then). */
int export_obj_mtllib(struct buf *obj, const char *mtl_name);
/* skeleton.json's "version": 2 since trees carry their vines (docs/skeleton-format.md,
 * Versions). */
#define SKELETON_VERSION 2
/* skeleton.json, see docs/skeleton-format.md: the tree, its "wood" when it was grown, and
 * its "vines" (vine_json.c) when it has any. */
int export_skeleton(const struct tree *t, struct buf *out);
/* skeleton.json with a "wind" object (docs/skeleton-format.md, "Wind"): the parameters
 * export_glb_wind's animation uses; none for a tree without branches or wind NULL (then
 * export_skeleton's bytes). 0, -EINVAL (as export_glb_wind) or -ENOMEM. */
int export_skeleton_wind(const struct tree *t, const struct export_wind *wind, struct buf *out);
struct vine;
/*
 * skeleton.json with a "vines" section (docs/skeleton-format.md, "Vines"; vine_json.h):
 * tree t's skeleton as export_skeleton writes it (an empty tree: the keys with nothing in
 * them), its "vines" the vines given, in place of t's own. Same vines, same bytes. What
 * `edaha --support` writes.
 */
int export_skeleton_vines(const struct tree *t, const struct vine *vines, size_t nvines,
			  struct buf *out);

/*
 * The take-home page (issue 28, docs/page.md): one self-contained HTML file that shows the
 * model turning under the mouse or a finger and playing its "wind", on the kiosk's paper,
 * with its number, its date and a line of words in the kiosk's language; it opens from a
 * file (a USB stick's tree-NNNN.html, a headless run's model.html) in any current browser,
 * offline. Everything is inline: the model in base64, the viewer's scripts (three.js, its
 * GLTFLoader and OrbitControls: passed in, as platform/ reads them from Debian's
 * libjs-three), edaha's own viewer script and style (src/export/page/), and a
 * Content-Security-Policy that lets nothing load from anywhere.
 *
 * Text never becomes markup: the number, the date and the words go into one
 * <script type="application/json"> with every <, > and & escaped (\u003c...), and the
 * viewer sets them as textContent. So the bytes before and after that JSON are the same
 * whatever the text (and, the model's base64 aside, whatever the model). No inlined script
 * holds "</script" or "<!--" (escaped as "<\/script", "\x3C!--": the same JavaScript in a
 * string or a regular expression, where such text is found). Same input, same bytes.
 */
enum export_page_lang { EXPORT_PAGE_EN, EXPORT_PAGE_JA, EXPORT_PAGE_NLANGS };

/* What the page says; "#" in number and title is the tree's number. */
struct export_page_words {
	const char *lang;     /* the page's language tag: "en", "ja" */
	const char *number;   /* "Tree No. #" */
	const char *title;    /* the window's title with a number */
	const char *untitled; /* ...and without one */
	const char *hint;     /* how to turn it */
	const char *nogl;     /* a browser without WebGL */
	const char *failed;   /* the model cannot be read */
};

/* One of the viewer's scripts, its bytes as read. */
struct export_page_script {
	const void *data;
	size_t len;
};

struct export_page {
	const void *glb; /* the model: export_glb_wind's bytes */
	size_t glb_len;
	/* three.min.js, GLTFLoader.js, OrbitControls.js: inlined in this order, before
	 * edaha's viewer */
	const struct export_page_script *scripts;
	size_t nscripts;
	unsigned number;  /* the set's number; 0: none shown (a headless run's page) */
	const char *date; /* as shown (export_page_date); NULL or "": none */
	const struct export_page_words *words; /* export_page_words(lang) */
	float paper[3];   /* the background, 0..1 (ui's render_paper) */
	/* The screen's colours of the bark, summer's leaves and a vine's stems, 0..1 (ui's
	 * render_bark, LEAF_TINT_SUMMER_RGB, render_vine_stem): the page shows each of the
	 * model's colours through the curve that takes the file's to the screen's, channel
	 * by channel, c^k with k = ln(screen) / ln(file), as the screen shows a season's
	 * (ui/leaf_tint.h). A channel outside (0, 1) keeps the file's colour. */
	float bark[3], leaves[3], stem[3];
};

/* The words of a language (a table in export_page.c); NULL past EXPORT_PAGE_NLANGS. */
const struct export_page_words *export_page_words(enum export_page_lang lang);
/* A day as the page says it: "5 December 2026", "2026ねん 12がつ 5にち". 0, or -EINVAL
 * (no such day, no such language) or -ENOSPC (out too small; out is "" then). */
int export_page_date(enum export_page_lang lang, int year, int month, int day, char *out,
		     size_t size);
/* Appends the page to out. 0, -EINVAL (no model, no words, a script without bytes) or
 * -ENOMEM; out as it was on failure. */
int export_page_html(const struct export_page *p, struct buf *out);
