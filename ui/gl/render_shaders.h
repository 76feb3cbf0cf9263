/* SPDX-License-Identifier: MIT */
#pragma once

/*
 * What every lit picture shares (render_shaders.c): the screen's tree (render.c), its
 * instanced leaves (render_instanced.c), a leaf alone (render_leaf.c) and a vine alone
 * (render_vine.c) are drawn by the same lit programs on the same paper. Data only: it
 * includes nothing of the renderer's.
 */

/* GLSL ES 1.00, so the same programs run on GLES 2 and 3: the tree program's shaders, and
 * the tinted programs' (a colour a vertex, `varying vec3 v_tint`, instead of u_color). The
 * instanced program has a vertex shader of its own and shares the fragment shaders. */
extern const char render_tree_vs[];
extern const char render_tree_fs[];
extern const char render_tinted_vs[];
extern const char render_tinted_fs[];
/* The living programs (LIVE defined; docs/living-trees.md, "The shader"): the same with
 * each vertex moved by the wind and the growth's pull (RENDER_LIVE_VS_DECLS) and, past the
 * growth's front, not drawn. */
extern const char render_live_vs[];
extern const char render_live_tinted_vs[];
extern const char render_live_fs[];
extern const char render_live_tinted_fs[];
/* Today's forest (FOREST defined, render_forest.c): the living programs with each tree's
 * trunk harmonic and phase per vertex (a_trunk) and the loop's fraction (u_loop_u), so
 * one frame sways every tree at its own rate; the living fragment shaders. */
extern const char render_forest_vs[];
extern const char render_forest_tinted_vs[];

/* The paper behind every picture. */
extern const float render_paper[3];
/* The bark as the screen colours it, in every view (lighter than the exporters', numfmt.h;
 * the take-home page maps the one to the other, export_page). */
extern const float render_bark[3];
/* A vine's young stem: darker and yellower than the leaves, so that a stem reads against
 * its own leaves (the exporters' vine colour, numfmt.h, as it is). */
extern const float render_vine_stem[3];

/* What the tinted vertex shaders (TINT defined: a colour a vertex or an instance, for spring
 * and autumn leaves) declare and pass on, the merged and the instanced alike. */
#define RENDER_TINT_VS_DECLS                                                               \
	"#ifdef TINT\n"                                                                    \
	"attribute vec3 a_tint;\n"                                                         \
	"varying vec3 v_tint;\n"                                                           \
	"#endif\n"
#define RENDER_TINT_VS_PASS                                                                \
	"#ifdef TINT\n"                                                                    \
	"	v_tint = a_tint;\n"                                                       \
	"#endif\n"

/*
 * What the living vertex shaders (LIVE defined) declare: a vertex's skeleton data
 * (render_live.c packs it: a_live0 the skeleton point and its path length d, a_live1 the
 * band weights w0..w3 as normalised shorts times u_wscale, a_phase the leaf's and bands'
 * phases in 1/256 turns, a_flutter the leaf's flutter direction x 127) and the frame's
 * uniforms (app_live_at). live_move(p) is where the vertex at rest at p is drawn: pulled
 * towards its skeleton point behind the growth's front (exactly p a swell behind it) plus
 * the wind, the sum live_wind_frame_offset computes (src/live/live_wind.c), its leaf
 * distance taken from p. u_unfolding 1: not pulled (an origami leaf drawn at its
 * unfolding keyframe instead, render_instanced_grow.c). v_front < 0: past the front, not
 * drawn (the fragment shader). The forest's caps it at the swell, so that a triangle
 * grown whole has one value all over it: multisampling takes a pixel's varyings at its
 * centre, outside a sliver that covers some of its samples, where the front's would be
 * extrapolated (below 0 on a steep one: a sample lost, a pixel off the settled frame).
 */
#define RENDER_LIVE_VS_DECLS                                                               \
	"#ifdef LIVE\n"                                                                    \
	"uniform vec3 u_along;\n"                                                          \
	"uniform vec3 u_across;\n"                                                         \
	"uniform vec2 u_sway;\n"                                                           \
	"uniform vec3 u_dir[3];\n"                                                         \
	"uniform vec4 u_theta;\n"                                                          \
	"uniform float u_amp_leaf;\n"                                                      \
	"uniform float u_front;\n"                                                         \
	"uniform float u_swell;\n"                                                         \
	"uniform vec4 u_wscale;\n"                                                         \
	"uniform float u_unfolding;\n"                                                     \
	"attribute vec4 a_live0;\n"                                                        \
	"attribute vec4 a_live1;\n"                                                        \
	"attribute vec4 a_phase;\n"                                                        \
	"attribute vec4 a_flutter;\n"                                                      \
	"#ifdef FOREST\n"                                                                  \
	"attribute vec2 a_trunk;\n"                                                        \
	"uniform float u_loop_u;\n"                                                        \
	"#endif\n"                                                                         \
	"varying float v_front;\n"                                                         \
	"vec3 live_move(vec3 p) {\n"                                                       \
	"	float k = 6.283185307179586 / 256.0;\n"                                    \
	"	vec4 w = a_live1 * u_wscale;\n"                                            \
	"#ifdef FOREST\n"                                                                  \
	"	float th = 6.283185307179586 * fract(a_trunk.x * u_loop_u + a_trunk.y / 256.0);\n" \
	"	vec2 sway = vec2(sin(th), sin(2.0 * th));\n"                              \
	"#else\n"                                                                          \
	"	vec2 sway = u_sway;\n"                                                     \
	"#endif\n"                                                                         \
	"	vec3 wind = w.x * (sway.x * u_along + sway.y * u_across)\n"                \
	"		+ w.y * sin(u_theta.x + a_phase.y * k) * u_dir[0]\n"             \
	"		+ w.z * sin(u_theta.y + a_phase.z * k) * u_dir[1]\n"             \
	"		+ w.w * sin(u_theta.z + a_phase.w * k) * u_dir[2]\n"             \
	"		+ u_amp_leaf * length(p - a_live0.xyz)\n"                        \
	"		  * sin(u_theta.w + a_phase.x * k) * (a_flutter.xyz / 127.0);\n" \
	"	float f = max(smoothstep(0.0, u_swell, u_front - a_live0.w), u_unfolding);\n" \
	"#ifdef FOREST\n"                                                                  \
	"	v_front = min(u_front - a_live0.w, u_swell);\n"                           \
	"#else\n"                                                                          \
	"	v_front = u_front - a_live0.w;\n"                                          \
	"#endif\n"                                                                         \
	"	return p * f + a_live0.xyz * (1.0 - f) + wind;\n"                          \
	"}\n"                                                                              \
	"#endif\n"
