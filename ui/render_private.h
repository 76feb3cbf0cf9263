/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * The renderer's state (struct render) and the layers the frame (render.c) draws with: the
 * meshes, instanced leaves, text, 2D layers, previews, a leaf or a vine alone (render_*.c).
 * Shared by the renderer's files; not for its users (tests and benches may poke at it).
 * The layers call no function of render.c's: what they share is below them, in render_gl.h
 * (GL helpers) and render_shaders.h (the lit programs' sources, the paper).
 */

#include <GLES2/gl2.h>
#include <stdbool.h>
#include <stdint.h>

#include "app.h"
#include "arrange.h"
#include "atlas.h"
#include "batch.h"
#include "camera.h"
#include "font.h"
#include "gen.h"
#include "leaf_instances.h"
#include "live.h"
#include "ori.h"
#include "render.h"
#include "render_gl.h"
#include "render_shaders.h"

struct app;
struct mesh;
struct tree;
struct font;
struct tree_mesh_marks;

/* What the 2D layers need to write words: the font (NULL: no words) and the language. */
struct ui_text {
	struct font *font;
	enum render_lang lang;
};

/* A tree mesh on the GPU. */
struct render_mesh {
	GLuint positions, normals, indices;
	GLuint tints;      /* leaves in a season of many colours: 3 floats a vertex */
	GLsizei count;     /* indices to draw, or vertices when not indexed */
	bool indexed;      /* false: expanded to a plain triangle list */
	size_t ntriangles;
	size_t bytes;      /* uploaded by the last render_mesh_upload */
};

/* A living program (render_live.c): a lit program's uniforms and the frame's. */
struct render_live_program {
	struct render_program_tree tree;
	GLint along, across, sway, dir, theta, amp_leaf, front, swell, wscale;
	GLint unfolding; /* 1: no pull, the leaf is drawn at its keyframe (instanced only) */
};

/*
 * Leaves drawn instanced (GLES 3, render_instanced.c): each shape leaf_instances finds
 * with copies is one mesh drawn once for all of them, each instance's 3x4 matrix a vertex
 * attribute that advances per instance; the leaves no other is a copy of, merged, drawn
 * as before with the tree program.
 */
struct render_instanced {
	/* plain (one colour) and tinted (a colour an instance, tints); and the living ones */
	struct render_program_tree plain, tinted;
	struct render_live_program live, live_tinted;
	GLuint tints;
	struct render_mesh shapes[LEAF_INSTANCES_MAX_SHAPES];
	size_t first[LEAF_INSTANCES_MAX_SHAPES], count[LEAF_INSTANCES_MAX_SHAPES];
	/* an origami shape's unfolding keyframes (leaf_shape.frames); none uploaded: 0 */
	struct render_mesh frames[LEAF_INSTANCES_MAX_SHAPES][ORI_UNFOLD_FRAMES];
	bool has_frames[LEAF_INSTANCES_MAX_SHAPES];
	size_t nshapes;
	GLuint matrices; /* 12 floats an instance, shape by shape */
	struct render_mesh loose;
	/* the grouping, kept between uploads: its arrays are reused (an edit regroups every
	 * leaf; warm, that is ~0.3 us a leaf on the 2-core VM) */
	struct leaf_instances li;
	/* While a tree grows in (render_instanced_grow.c): every instance again, an origami
	 * shape's sorted by their anchors' path length d (grow_d, ascending), so that the
	 * leaves at one unfolding keyframe are one range; grow_order[i] is the instance at
	 * i; the matrices and tints in that order (the living data: render_live's
	 * grow_instances). grow_ok: built for the instances uploaded. */
	size_t *grow_order;
	float *grow_d;
	size_t grow_cap;
	GLuint grow_matrices, grow_tints;
	bool grow_ok;
};

/* A side strip picture on the GPU: a copy of one of the app's previews[] or templates[]
 * (render_preview.c), as of a previews_serial. */
struct render_picture {
	struct render_mesh bark, leaves;
	bool uploaded;
	uint64_t serial;
	double bounds[4]; /* a template's, through the template camera: x0, y0, x1, y1 */
	enum season season; /* a template's: its preset's */
};
#define RENDER_PICTURES (ARRANGE_COUNT + GEN_PRESET_COUNT)

/* A mesh's living data on the GPU (render_live.c), 32 bytes a vertex or an instance. */
#define RENDER_LIVE_STRIDE 32
struct render_live_data {
	GLuint vbo;
	bool ok; /* holds the data of the mesh it is for */
};

/* The living tree's programs and data (render_live.c). */
struct render_live {
	struct render_live_program merged, merged_tinted;
	/* the data of the tree's meshes as uploaded (tree_ok: bound since the last upload),
	 * of the wood's bark (wood_of at wood_serial) and of the vines (at vines_of) */
	struct render_live_data bark, leaves, loose, instances, wood, vine[4];
	/* the instances' data in the growth's order (render_instanced's grow_order) */
	struct render_live_data grow_instances;
	bool tree_ok, wood_ok, vines_ok;
	const struct mesh *wood_of;
	uint64_t wood_serial, vines_of, vines_mesh_of;
	float wscale[4];               /* the band weights' scales (the shader's u_wscale) */
	struct app_live_frame frame;   /* this frame's */
	bool on;                       /* this frame is drawn by the living programs */
	size_t bytes;                  /* the data this frame uploaded */
	/* scratch, kept between bindings */
	struct live_attrs attrs;
	struct live_vertex *gather;
	size_t gather_cap;
	void *packed;
	size_t packed_cap;
	bool *inst_mark;
};

/* The trees' numbers of today's forest on the GPU (render_forest.c): every label's quads
 * built once a scene (of at serial), at px pixels to the em with the font's digits where
 * they were then (digits[d] for each digit d in `used`); its program projects each
 * vertex's tree foot and adds the vertex's pixel offset. */
struct render_forest_labels {
	GLuint program;
	GLint mvp, screen, texel, atlas, card, ink;
	GLuint vbo;
	GLsizei count;      /* vertices */
	const struct forest_scene *of;
	uint64_t serial;
	const struct font *font;
	int px;
	unsigned used;      /* bit d: digit d is in a number */
	struct font_glyph digits[10];
	bool ok;
	size_t builds;      /* how many times they were built (tests, benchmarks) */
};

/* Today's forest on the attract screen (render_forest.c): its programs, the scene's meshes
 * and data as they went up (of at serial), this frame's matrix, and the numbers. */
struct render_forest {
	struct render_live_program plain, tinted;
	GLint loop_u[2];
	struct render_mesh bark, leaves, ground;
	struct render_live_data bark_live, leaves_live;
	GLuint bark_trunk, leaves_trunk;
	float wscale[4];
	const struct forest_scene *of;
	uint64_t serial;
	bool ok, tinted_leaves;
	bool tinted_bark; /* a vine's stems among the bark: the bark drawn with vertex colours */
	bool drawn;              /* this frame */
	float mvp[16];           /* this frame's world to clip */
	struct render_forest_labels labels;
};

/* What a frame of the forest needs, all of it computed on the CPU before any GL call
 * (render_forest_frame_at): O(1), whatever the number of trees. */
struct render_forest_frame {
	float mvp[16], light[3];
	struct app_live_frame live; /* the wind's numbers; every tree drawn whole */
	double loop_u;              /* the wind's loop's fraction */
	bool growing;               /* the newest tree grows in: */
	double age, front, swell;   /* its age (s), its growth's front and swell (m) */
};

struct render {
	/* this frame's unfolding leaves (app_unfold_at) */
	struct app_unfold_span unfold[APP_UNFOLD_MAX];
	size_t nunfold;
	/* lit tree meshes: world positions and normals */
	GLuint tree_program;
	GLint tree_mvp, tree_color, tree_light, tree_two_sided;
	/* the same with a colour a vertex (ATTR_TINT): leaves in spring and autumn */
	struct render_program_tree tinted;
	/* the lit program the tree is being drawn with: the tree program, or a living one */
	struct render_program_tree lit;
	struct render_live live;
	struct render_forest forest;
	/* screen-space triangles, flat or showing the atlas's glyphs */
	GLuint flat_program;
	GLint flat_proj, flat_texel, flat_atlas;
	GLuint flat_vbo;
	/* the glyphs (and the solid texel) on the CPU and their GL copy */
	struct atlas atlas;
	GLuint atlas_texture;
	int atlas_max;
	struct ui_text text;

	/* GLES 3 or OES_element_index_uint; without it meshes are expanded on upload */
	bool uint_indices;

	/* GLES 3 with the instanced program: leaves of app->tree are drawn instanced (tests
	 * may turn it off to draw the merged app->mesh.leaves, as GLES 2 does) */
	bool instanced;

	struct render_mesh bark, leaves;
	struct render_mesh wood; /* the tree's wood's bark (app_wood_bark_at), or empty */
	const struct mesh *wood_src; /* what wood holds (NULL: nothing known) */
	uint64_t wood_serial;        /* ...of the tree at this mesh_serial */
	uint64_t frame_us;           /* the time render_frame_at draws */
	struct render_instanced inst;
	bool uploaded;       /* the meshes hold mesh_serial's tree */
	bool uploaded_instanced; /* ...its leaves in inst, not in leaves */
	bool uploaded_tinted;    /* ...with a colour each (leaf_colors_vary) */
	enum season uploaded_season;
	uint64_t mesh_serial;
	float *tint_scratch;     /* the colours on their way to the GPU, kept between uploads */
	size_t tint_cap;         /* in floats */
	size_t upload_bytes; /* what the last upload of the tree sent to the GPU */

	/* the vines (app->vines_mesh, app->growth.mesh) as of vines_serial */
	struct render_mesh vine_stems, vine_leaves, grow_stems, grow_leaves;
	bool vines_uploaded;
	uint64_t vines_serial;

	/* the side strip's pictures: the leaf suggestions', then the templates' */
	struct render_picture pictures[RENDER_PICTURES];

	struct batch batch;
	struct render_stats stats;
};

/* render_leaf.c: world -> clip for a frame of its own (a leaf, a vine): the camera xf,
 * then the meshes' view-space box centred and scaled to fill width x height but for margin
 * (1.12: an eighth of their size), their depth filling the depth range. */
void render_fit_matrix(const struct mesh *const *meshes, size_t nmeshes,
		       const struct camera_xf *xf, int width, int height, double margin,
		       float out[16]);
/* render.c: uploads the tree's meshes if mesh_serial changed (render_frame does it
 * first): for benchmarks. 0 or a negative errno. */
int render_upload_tree(struct render *r, const struct app *app);

/* render_vine.c: the app's vines drawn with the tree program in use (uploaded first when
 * vines_serial changed), their stems render_vine_stem's green; leaves in the season's
 * colour. 0 or a negative errno. */
int render_vines_draw(struct render *r, const struct app *app);
void render_vines_finish(struct render *r);

/*
 * render_live.c: the living tree. create: the merged living programs (0, or -1: stderr
 * says why; the tree then stands still); clear: the data's GPU copies; finish: all.
 * begin: whether this frame is drawn living (the app's tree moves at now_us, its
 * skeleton is the uploaded meshes' and their data is bound: bound here when they
 * changed); vines: whether the vines are drawn (not while the tree grows in; their data
 * bound when they changed). use: a living program in use with the frame's uniforms
 * (r->lit its lit uniforms). draw: rm with its data d (the still way when the frame is
 * not living). pointers: the data's four attributes from vbo at instance or vertex
 * `first`, at locations base..base + 3.
 */
int render_live_create(struct render *r);
void render_live_clear(struct render *r);
void render_live_finish(struct render *r);
void render_live_program_locate(struct render_live_program *p);
bool render_live_begin(struct render *r, const struct app *app, uint64_t now_us);
bool render_live_vines(struct render *r, const struct app *app);
void render_live_uniforms(const struct render *r, const struct render_live_program *p);
void render_live_use(struct render *r, const struct render_live_program *p, const float mvp[16],
		     const float light[3]);
void render_live_draw(struct render *r, const struct render_mesh *rm,
		      const struct render_live_data *d, bool tinted);
void render_live_pointers(GLuint vbo, GLuint base, size_t first);
/* v[0..n)'s data into d's buffer, the band weights against wscale, expanded by m's
 * indices when the mesh went up without them (render_mesh.c's GLES 2 fallback): one a
 * vertex as drawn. 0, -ENOMEM or -EINVAL. */
int render_live_upload(struct render *r, struct render_live_data *d, const struct live_vertex *v,
		       size_t n, const struct mesh *m, bool expand, const float wscale[4]);
/* A living program's uniforms for frame f, band weights scaled by wscale. */
void render_live_frame_uniforms(const struct render_live_program *p, const struct app_live_frame *f,
				const float wscale[4]);

/* render_mesh.c */
int render_mesh_upload(struct render_mesh *rm, const struct mesh *m, bool uint_indices);
/* A colour for every vertex of m, which rm was uploaded from (3 floats a vertex);
 * 0 or -ENOMEM. */
int render_mesh_upload_tints(struct render_mesh *rm, const struct mesh *m, const float *rgb);
void render_mesh_draw(struct render *r, const struct render_mesh *rm);
/* With a tinted program in use: the mesh with its vertices' colours. */
void render_mesh_draw_tinted(struct render *r, const struct render_mesh *rm);
void render_mesh_finish(struct render_mesh *rm);
/* Room for n floats of colours on their way to the GPU (r->tint_scratch), or NULL. */
float *render_tint_scratch(struct render *r, size_t n);

/* render_instanced.c (GLES 3 only). create: 0, or -1 (stderr says why; draw merged).
 * upload: the shapes, their matrices and the loose leaves of t (`merged`, t's leaves
 * mesh, when no shape has copies; mk its marks), and with `tinted` every leaf's colour in
 * t's season (leaf_tint.h); 0 or a negative errno (then nothing is drawn until the next
 * upload). draw: with the tree program's lighting, in one colour (color) or, color NULL,
 * each instance its own; counted in r->stats. */
int render_instanced_create(struct render *r);
int render_instanced_upload(struct render *r, const struct tree *t, const struct mesh *merged,
			    const struct tree_mesh_marks *mk, bool tinted);
/* The instanced leaves; those in spans (leaf order) at their unfolding keyframes. */
void render_instanced_draw(struct render *r, const float mvp[16], const float light[3],
			   const float color[3], const struct app_unfold_span *spans,
			   size_t nspans);
/* render_instanced_grow.c: the growth's order of the instances uploaded, from v, their
 * living data in instance order; their matrices and tints (tinted) uploaded in it. 0 or
 * -ENOMEM (grow_ok false: the origami leaves then scale in like the others). drop: its
 * GPU copies freed, grow_ok false. */
int render_instanced_grow_order(struct render *r, const struct tree *t,
				const struct live_vertex *v, bool tinted);
void render_instanced_grow_drop(struct render *r);
/* Frees the GPU copies (the program stays until finish). */
void render_instanced_clear(struct render *r);

/* render_forest.c: today's forest on the attract screen, its GPU copy known by the
 * scene's address and serial (the platform keeps one scene and builds it again).
 * create: 0, or -1 (stderr says why; the attract screen then shows the drawing, as
 * before). shown: whether the frame at now_us shows it (app_forest_at, and the programs
 * are there). draw: the ground and the trees in the canvas (the newest tree growing in
 * while it does); 0 or a negative errno. labels: each tree's number at its foot, after
 * draw, in one call of their own (under what the batch holds). */
int render_forest_create(struct render *r);
void render_forest_finish(struct render *r);
bool render_forest_shown(const struct render *r, const struct app *app, uint64_t now_us);
int render_forest_draw(struct render *r, const struct app *app, uint64_t now_us);
void render_forest_labels(struct render *r, const struct app *app);
/* The CPU's part of a frame of app->forest (a scene with a tree) at now_us: the camera,
 * the wind's numbers, the newest tree's growth (app->forest_joined_us); no GL. */
void render_forest_frame_at(const struct app *app, uint64_t now_us,
			    struct render_forest_frame *out);
/* Whether the numbers' quads on the GPU are the scene's at this screen's size and font
 * (else render_forest_labels builds them again): O(1), no GL. */
bool render_forest_labels_current(struct render *r, const struct app *app);
void render_instanced_finish(struct render *r);

/* render_text.c: the atlas and its texture. init: 0 or -ENOMEM (stderr says why). sync:
 * uploads what changed since the last sync, binds the texture; 0 or -ENOMEM. */
int render_text_init(struct render *r);
int render_text_sync(struct render *r);
void render_text_finish(struct render *r);

/* render_ui.c: the 2D layers, added to r->batch. */
void render_ui_ground(struct batch *b, const struct app *app);
void render_ui_stroke(struct batch *b, const struct app *app);
void render_ui_buttons(struct batch *b, const struct ui_text *t, const struct app *app);
/* A button label's size for a button h pixels tall, and the width it may take in one w
 * wide (a longer label is set smaller). */
int render_ui_label_px(double button_h);
double render_ui_label_room(double button_w);
/* A named card's word's size, for the band of that height under its picture. */
int render_ui_card_label_px(double band);
void render_ui_cursor(struct batch *b, const struct app *app);
/* The branch clone mode works on, marked over the tree as the camera xf shows it. */
void render_ui_selection(struct batch *b, const struct app *app, const struct camera_xf *xf);

/* render_overlay.c: over the canvas, under the cursor: the status message at now_us, and
 * the attract screen. */
void render_ui_status(struct batch *b, const struct ui_text *t, const struct app *app,
		      uint64_t now_us);
/* forest: today's forest is on screen (the invitation as a band at the canvas's foot). */
void render_ui_attract(struct batch *b, const struct ui_text *t, const struct app *app,
		       bool forest);

/* render_preview.c: the 3D pictures in the side strip's cards (the cards behind them are
 * render_ui_buttons'): whether there are any, and drawing them, the leaf suggestions seen
 * through xf. 0 or a negative errno. */
bool render_previews_shown(const struct app *app);
int render_previews(struct render *r, const struct app *app, const struct camera_xf *xf,
		    const float light[3]);
void render_previews_finish(struct render *r);
