/* SPDX-License-Identifier: MIT */
/*
 * src/app/ (floor 9 of src/FLOORS, the top of src/): the application: modes, the op
 * and hook tables, history, status. Includes anything below; platform/ and ui/ build on it.
 */
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "arrange.h"
#include "camera.h"
#include "doc.h"
#include "event.h"
#include "forest.h"
#include "gen.h"
#include "history.h"
#include "live.h"
#include "mesh.h"
#include "rng.h"
#include "tree.h"
#include "screen.h"
#include "vine.h"
#include "wood.h"

/*
 * The kiosk's state machine. It consumes struct event only and owns the document,
 * the tree rebuilt from it and the meshes. The renderer (ui/) reads it; platform/
 * feeds it and takes its requests (export: the kiosk writes to USB; a headless run
 * writes its files at the end in any case). Pure: no I/O, no clock.
 */

enum app_mode {
	APP_MODE_SKETCH = 0,
	APP_MODE_CLONE,
	APP_MODE_LEAF,
	APP_MODE_PROPAGATE,
	APP_MODE_NEW, /* the New strip: templates to start from (app_mode_new.c) */
	APP_MODE_VINE, /* a tap at the tree's foot plants a twining vine (app_mode_vine.c) */
	APP_MODE_COUNT, /* a new mode: before this, and a row in app_modes.c's table */
};

/* Propagation pattern: until a pattern button is pressed, fixed count for a branch with
 * child branches, fixed size for one with leaves only (section 3.6). */
enum app_pattern {
	APP_PATTERN_AUTO = 0,
	APP_PATTERN_FIXED_COUNT,
	APP_PATTERN_FIXED_SIZE,
};

/* Bits returned by app_take_requests(). */
enum app_request {
	APP_REQUEST_EXPORT = 1u << 0,
	/* a grow press to make off the loop (grow_async: app_grow_job, app_grow_done) */
	APP_REQUEST_GROW = 1u << 1,
	/* with EXPORT: Save was pressed while today's forest was on screen: the forest too */
	APP_REQUEST_FOREST = 1u << 2,
};

/*
 * Short messages the kiosk shows over the canvas for APP_STATUS_US after the platform
 * reports how something it was asked for went (ui/ has their words in each language).
 * Extend at the end: the values are not stored anywhere, but tests name them.
 */
enum app_status {
	APP_STATUS_NONE = 0,
	APP_STATUS_SAVED,       /* the export was written */
	APP_STATUS_SAVE_FAILED, /* the export could not be written */
	/* USB export (platform/usb/usb_export.c) */
	APP_STATUS_SAVING,       /* being written to the stick: held until the result */
	APP_STATUS_SAVED_USB,    /* on the stick, which is unmounted: safe to take out */
	APP_STATUS_NO_STICK,     /* save pressed with no stick in */
	APP_STATUS_STICK_PULLED, /* the stick came out before the save was done */
	APP_STATUS_STICK_FULL,   /* no room on the stick */
	APP_STATUS_STICK_LOCKED, /* write-protected, read-only */
	APP_STATUS_STICK_UNUSABLE, /* unformatted, unsupported or a hostile layout */
	APP_STATUS_STICK_READY,  /* a stick was put in and can be saved to */
	/* the vine mode (issue 16) */
	APP_STATUS_VINE_TAP,     /* entered: tap the ground by the trunk to plant a vine */
	APP_STATUS_VINE_WHERE,   /* a tap too far from the tree: tap by the trunk's foot */
	APP_STATUS_VINE_FULL,    /* the tree has as many vines as it takes */
	APP_STATUS_GROWING,      /* a grow press under way (the kiosk's): held until done */
	/* today's forest (issue 27): "Your tree is No. N in today's forest" (status_number) */
	APP_STATUS_IN_FOREST,
	APP_STATUS_COUNT,
};
#define APP_STATUS_US 4000000u
#define APP_STATUS_FADE_US 500000u /* the last part of it, fading out */
/* With nothing touched for this long the kiosk shows its attract screen (0: never). */
#define APP_ATTRACT_US_DEFAULT (90u * 1000000u)

struct app_point {
	double x, y; /* screen pixels */
	double pressure;
	uint64_t time_us;
};

/* The stroke under the pen, in screen pixels, drawn live. */
struct app_stroke {
	struct app_point *points;
	size_t npoints, cap;
	enum event_tool tool;
	bool active; /* tip is down */
};

/*
 * Orbiting a 3D tree: a pen drag that starts on empty canvas, farther than this from
 * every branch and leaf on the screen, turns the camera instead of drawing (metres on
 * the screen: 12% of its height). Closer in, strokes and gestures work as in 2D: a cut
 * begins at least 2 x GESTURE_SNAP_M before its crossing, so slashes from up to here
 * stay cuts.
 */
#define APP_ORBIT_CLEARANCE_M 1.2
/* A tap selects the branch it lands within this of on the screen (metres; 3%). */
#define APP_TAP_M 0.3
/* A clone-mode circle: the pen goes at least this far round its centre (radians), and
 * the stroke is at least this long (metres). */
#define APP_CIRCLE_TURN (1.5 * 3.14159265358979323846)
#define APP_CIRCLE_MIN_M 0.3

/* Degrees the camera turns per metre the pen drags (half a screen height: 90 degrees). */
#define APP_ORBIT_DEG_PER_M 18.0
/* After 3D is pressed the tree swings this far to one side and the other, and back. */
#define APP_TURN_US 2400000u
#define APP_TURN_DEG 40.0

struct app_pen {
	bool in_proximity;
	enum event_tool tool;
	double x, y, pressure, tilt_x, tilt_y;
	bool stylus, stylus2;
};

/* A new origami leaf unfolds from the bud over this long (docs/origami-leaves.md). */
#define APP_UNFOLD_US 1000000u
#define APP_UNFOLD_MAX 8

/* Leaves [first, end) unfolding, at keyframe `frame` of ORI_UNFOLD_FRAMES. */
struct app_unfold_span {
	size_t first, end;
	unsigned frame;
};

/*
 * A vine planted in the vine mode grows on screen by the events' time, this many axis
 * points a second (6 internodes of the default 8 points): its apex visibly circles, finds
 * the trunk and winds up it. The model holds it grown to its end all along.
 */
#define APP_VINE_POINTS_PER_S 48.0
/* The vine preset the kiosk plants (presets/vines/), scaled to the tree. */
#define APP_VINE_PRESET "morning-glory"

struct vine_support;

/* The vine growing on screen: the tree's last vine, regrown step by step (app_vine.c). */
struct app_vine_growth {
	bool on;
	uint64_t start_us;
	struct vine v;
	struct vine_support *support; /* the bark it was planted on */
	struct tree_mesh mesh;        /* v as grown so far: stems (bark) and leaves */
};

/*
 * The living tree (app_live.c, docs/living-trees.md): the wind, and a tree growing in from
 * the trunk's foot when it becomes 3D, by the events' clock. The skeleton (live.h) is kept
 * in step with the meshes (sk_of: the mesh_serial it is of) while the wind blows or a
 * tree grows in; the renderer binds its meshes' vertices to it.
 */
/* The wind's direction at t = 0 (radians about y: +x, across the screen); it drifts. */
#define APP_WIND_ANGLE 0.0
struct app_live {
	double strength;         /* the wind, 0..1; 0 (the default): still */
	bool grow_in;            /* trees grow in (default true) */
	bool growing;            /* a growth from grow_start_us, for grow_us */
	uint64_t grow_start_us, grow_us;
	struct live_grow grow;   /* its front */
	struct live_skeleton sk; /* of the tree at mesh_serial sk_of, when sk_valid */
	struct live_wind wind;   /* sk's, at strength */
	bool sk_valid;
	uint64_t sk_of;
	/* a loaded drawing's vine op whose vine climbs once the growth ends (SIZE_MAX: none) */
	size_t vine_op;
};

/* What the renderer's living programs need at a moment (app_live_at). */
struct app_live_frame {
	bool moving;  /* the wind blows or the tree grows in: drawn by the living programs */
	bool growing; /* the tree grows in: no vine is drawn yet */
	double front, swell;         /* the growth's front and swell (live_grow.c), metres */
	struct live_wind_frame wind; /* all amplitudes 0 when still */
};

struct app {
	struct screen screen; /* pixels <-> the sketch plane */
	struct doc doc;       /* strokes, history, seed: what drawing.edaha holds */
	struct tree tree;     /* rebuilt from doc */
	struct rng rng;       /* state after applying doc up to its cursor */
	struct tree_mesh mesh;
	struct tree_mesh_marks mesh_marks; /* where each element's part of mesh begins */
	uint64_t mesh_serial; /* bumped whenever tree/mesh change, so the renderer re-uploads */
	struct history history; /* states along doc's history, for undo and redo */
	struct tree before;     /* the tree an undo or redo leaves, while meshes are reused */
	/* New pressed after something was drawn (issue 27): that drawing, for the kiosk to
	 * archive and plant in today's forest: the tree as it stood and the ops in effect
	 * then (doc.ops[0..cursor)); app_take_replaced hands it over. */
	struct {
		bool pending;
		struct tree tree;
		size_t cursor;
	} replaced;
	struct app_stroke stroke;
	struct app_pen pen;
	enum app_mode mode;
	enum app_pattern pattern;
	bool buttons_down[BUTTON_COUNT];
	/* The on-screen button the pen tip is holding down, if any. */
	bool ui_button_held;
	enum button ui_button;
	/* The camera strokes are drawn in; the front view unless the tree is 3D. */
	struct camera camera;
	bool orbiting;             /* the pen tip is turning the camera */
	double orbit_x, orbit_y;   /* where the pen was, screen pixels */
	double orbit_x0, orbit_y0; /* where the tip went down */
	uint64_t orbit_t0_us;
	uint64_t turn_start_us;    /* the animated turn after lifting, when turning */
	bool turning;
	/* Leaves an edit made from [first, ...) unfolding since start_us, oldest first; each
	 * runs to the next one's first or the tree's last leaf. */
	struct app_unfold {
		size_t first;
		uint64_t start_us;
	} unfold[APP_UNFOLD_MAX];
	size_t nunfold;
	/* The vines' meshes (stems as `bark`), the one growing left out, for the renderer:
	 * rebuilt when the tree's meshes change (mesh_serial) or a growth ends. */
	struct tree_mesh vines_mesh;
	uint64_t vines_mesh_of; /* the mesh_serial it was built for */
	bool vines_mesh_growing; /* ...with growth on */
	uint64_t vines_serial;  /* bumped when vines_mesh or growth.mesh changes */
	struct app_vine_growth growth;
	/* The index of the tree's bark a vine tap built to find where it plants, lent to the
	 * vine op it pushes (bark_index_op) and on to the growth that op starts: one index a
	 * tap, not three. NULL outside a tap. */
	struct vine_support *bark_index;
	const struct doc_op *bark_index_op;
	/* What a grow press grows with (issue 17; wood.h): the defaults, or --wood's file. */
	struct wood_params wood_settings;
	/* The last press swells on screen from then (UINT64_MAX: nothing swells). */
	uint64_t swell_start_us;
	/* The kiosk makes a grow press off its loop (it sets grow_async): the button asks
	 * (APP_REQUEST_GROW, grow_waiting) and the press lands when the platform hands back
	 * the grown tree (app_grow_done), lent to the op it pushes. */
	bool grow_async;
	bool grow_waiting;
	struct tree *grow_lent;
	const struct doc_op *grow_lent_op;
	/* Example-based editing. */
	int selected;              /* clone mode: the branch that gets children, or -1 */
	int suggest_branch;        /* leaf mode: the branch whose leaves suggest... */
	unsigned suggestions;      /* ...these arrangements (1u << enum arrange_pattern) */
	struct tree_mesh previews[ARRANGE_COUNT]; /* their thumbnails' meshes */
	/* The New strip's thumbnails: the presets, made the first time the strip opens. */
	struct tree_mesh templates[GEN_PRESET_COUNT];
	bool templates_ready;
	uint64_t previews_serial;  /* bumped when either changes */
	bool side_held;            /* the pen tip is on a thumbnail */
	uint64_t last_time_us;     /* of the last event: idle time counts from it */
	uint64_t attract_after_us; /* idle time before the attract screen; 0: never */
	enum app_status status;    /* the last message, shown from status_us on */
	uint64_t status_us;
	bool status_held;          /* shown until the next one, not for APP_STATUS_US */
	uint32_t requests;
	struct app_live live;      /* the wind and growing in (app_live.c) */
	/* today's forest, the platform's (docs/forest.md): what the attract screen shows
	 * when it holds a tree; NULL: the attract screen over the drawing */
	const struct forest_scene *forest;
	/* when the scene's newest tree (its last) joined, by the app's clock: it grows in
	 * from then (0: none grows; every tree stands grown) */
	uint64_t forest_joined_us;
	/* the number the drawing on the canvas will have in today's forest once archived (0:
	 * not known, no forest); told beside Save's result */
	uint64_t forest_number;
	/* APP_STATUS_IN_FOREST's number */
	uint64_t status_number;
	/* the event being handled came while the forest was on screen (Save then takes the
	 * forest home too: APP_REQUEST_FOREST) */
	bool event_on_forest;
	int failed; /* first negative errno from an allocation, sticky */
};

struct app *app_create(int width, int height, uint64_t seed);
void app_destroy(struct app *app);
/* Replaces the document (takes ownership of *doc's contents) and rebuilds. 0 or -ENOMEM. */
int app_load_doc(struct app *app, struct doc *doc);
/* A new visitor: an empty drawing with this seed, sketch mode, the front view; not
 * undoable (the kiosk archives the old drawing first). 0 or -ENOMEM. */
int app_reset(struct app *app, uint64_t seed);
/*
 * The drawing New replaced, if one is waiting (app->replaced): true, with *t its tree
 * (moved out: tree_finish it) and *cursor the ops of app->doc in effect then; false when
 * none. A drawing New found empty, or a second New before the first was taken, replaces
 * nothing more: the first is kept.
 */
bool app_take_replaced(struct app *app, struct tree *t, size_t *cursor);
/* Shows t (taken: t is left empty) on the canvas with its meshes, outside the history:
 * for the benchmarks, whose trees (synthetic, up to 20,000 leaves) no drawing makes. The
 * drawing is left as it was; app_rebuild or a load shows its tree again. 0 or -ENOMEM. */
int app_show_tree(struct app *app, struct tree *t);
void app_handle_event(struct app *app, const struct event *ev);
uint32_t app_take_requests(struct app *app);
/* The camera to show at now_us: the settled one, or a step of the animated turn into 3D
 * (UINT64_MAX: the settled one). Returns true while the turn runs, so that the kiosk
 * keeps drawing frames. */
bool app_camera_at(const struct app *app, uint64_t now_us, struct camera *out);
/* The origami leaves still unfolding at now_us (UINT64_MAX: none, all settled), their
 * keyframes: at most max spans into out, in leaf order. */
size_t app_unfold_at(const struct app *app, uint64_t now_us, struct app_unfold_span *out,
		     size_t max);
/*
 * Grows the vine planted last to what the screen shows at now_us (UINT64_MAX: grown to its
 * end), and keeps the vines' meshes in step. The platform calls it before drawing a frame.
 * True while a vine is still growing, so that the kiosk keeps drawing frames. A failure
 * to grow it (no memory) ends the growth: the vine shows grown.
 */
bool app_vines_advance(struct app *app, uint64_t now_us);
/*
 * A grow press off the loop (grow_async). job: the tree to grow (a copy into *copy, an
 * initialised tree), the settings and the serial it is of; 0 or -ENOMEM. done: the copy,
 * grown with wood_grow on any thread, becomes the app's tree as a grow op at now_us (the
 * copy then holds the tree before, for the caller to free); -EAGAIN when the app's tree
 * changed meanwhile (the caller grows a new job's), 0 when no press waits any more (the
 * copy is the caller's), or -ENOMEM.
 */
int app_grow_job(const struct app *app, struct tree *copy, struct wood_params *p,
		 uint64_t *serial);
int app_grow_done(struct app *app, struct tree *grown, uint64_t serial, uint64_t now_us);
/* A grow press's bark swells on screen over this long, by the events' time (wood.h's
 * WOOD_SWELL_FRAMES frames). */
#define APP_SWELL_US 1000000u
/* The wood's bark to show at now_us (UINT64_MAX: at rest): a frame of the last press's
 * swelling while it lasts, else the bark; NULL without wood. */
const struct mesh *app_wood_bark_at(const struct app *app, uint64_t now_us);
/*
 * The living tree (app_live.c). app_set_wind: the wind's strength, 0..1 (0: still, the
 * default; LIVE_WIND_DEFAULT_STRENGTH a breeze); 0, -EINVAL (outside 0..1: nothing
 * changes) or -ENOMEM (the tree stands still until the next change). app_set_grow_in:
 * whether a tree grows in when it becomes 3D (default true); off stops a growth.
 */
int app_set_wind(struct app *app, double strength);
void app_set_grow_in(struct app *app, bool on);
/*
 * Whether the tree moves at now_us (UINT64_MAX, the settled view: never); out NULL, or
 * today's forest shows (app_forest_at: it moves by itself, the kiosk draws frames). And,
 * out not NULL, what the living programs need then: the growth's front while the tree grows in
 * (a pen tip or button put down finishes it), the wind's frame at its drifting angle.
 * O(1): the same few numbers whatever the tree.
 */
bool app_live_at(const struct app *app, uint64_t now_us, struct app_live_frame *out);
/* Whether the tree grows in at now_us; and when its growth ends (0: none runs). */
bool app_live_growing_at(const struct app *app, uint64_t now_us);
uint64_t app_live_grow_end(const struct app *app);
/* The skeleton of the tree as meshed now (mesh_serial), or NULL when nothing lives (or
 * it could not be made). */
const struct live_skeleton *app_live_skeleton(const struct app *app);
/* Turns a 3D tree's camera (as orbiting would). False, and nothing changes, for a sketch. */
bool app_set_camera(struct app *app, struct camera c);
/* The suggestion thumbnails shown, in order: how many, and their patterns. */
size_t app_suggestions(const struct app *app, enum arrange_pattern out[ARRANGE_COUNT]);
/* Whether a pen tip put down at screen pixel (x, y) would turn the camera. */
bool app_would_orbit(const struct app *app, double x, double y);
/* The platform's answer to a request (or any news for the visitor), shown from now_us. */
void app_set_status(struct app *app, enum app_status status, uint64_t now_us);
/* The same, shown until the next status replaces it (something under way: saving). */
void app_hold_status(struct app *app, enum app_status status, uint64_t now_us);
/* "Your tree is No. number in today's forest", from now_us. */
void app_tell_forest_number(struct app *app, uint64_t number, uint64_t now_us);
/* The platform's: the number the canvas's drawing will have in today's forest (0: none). */
void app_set_forest_number(struct app *app, uint64_t number);
/* The message on screen at now_us (APP_STATUS_NONE when none), and until when it shows. */
enum app_status app_status_at(const struct app *app, uint64_t now_us, uint64_t *until_us);
/* Whether the attract screen shows at now_us; *from_us says when it does (or did) begin
 * (UINT64_MAX: never, attract_after_us is 0). Any event ends it. */
bool app_attract_at(const struct app *app, uint64_t now_us, uint64_t *from_us);
/* Whether the attract screen at now_us shows today's forest: it is on, and app->forest
 * (the platform's) holds a tree. */
bool app_forest_at(const struct app *app, uint64_t now_us);
/* Rebuilds tree and meshes from the document up to its cursor. 0 or -ENOMEM. */
int app_rebuild(struct app *app);
/* Puts the tree p describes on the canvas, as a template tap does (--generate): one
 * undoable op. 0, -ENOMEM. */
int app_generate(struct app *app, const struct gen_params *p, uint64_t time_us);
/* Puts branches (a tree of branches only, as skeleton_read gives) on the canvas as one
 * undoable import op (--skeleton); branches is left empty. 0, -ENOMEM, or -ENOSPC (past
 * a DOC_MAX_ limit: nothing changed). */
int app_import(struct app *app, struct tree *branches, uint64_t time_us);
/* The generate op of the tree on the canvas while nobody has edited it by hand (season
 * changes aside), or NULL: the parameter buttons work on it. */
const struct doc_op *app_generated(const struct app *app);
/* Whether parameter button b would change the generated tree (at a limit it would not). */
bool app_gen_possible(const struct app *app, enum button b);
