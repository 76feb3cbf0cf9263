/* SPDX-License-Identifier: MIT */
/*
 * The lit programs' GLSL and the paper: what the screen's tree, its instanced leaves, a
 * leaf alone and a vine alone share, so that each is lit and coloured as the others.
 */
#include "render_shaders.h"

/* GLSL ES 1.00 so the same shaders run on GLES 2 and 3. With TINT defined, each vertex
 * has its own colour (leaves in spring and autumn); without, the program is the one it
 * always was, and summer's pixels are too. */
#define TREE_VS                                                                            \
	"uniform mat4 u_mvp;\n"                                                            \
	"attribute vec3 a_position;\n"                                                     \
	"attribute vec3 a_normal;\n"                                                       \
	"varying vec3 v_normal;\n"                                                         \
	RENDER_TINT_VS_DECLS                                                               \
	RENDER_LIVE_VS_DECLS                                                               \
	"void main() {\n"                                                                  \
	"	v_normal = a_normal;\n"                                                   \
	RENDER_TINT_VS_PASS                                                                \
	"#ifdef LIVE\n"                                                                    \
	"	gl_Position = u_mvp * vec4(live_move(a_position), 1.0);\n"                \
	"#else\n"                                                                          \
	"	gl_Position = u_mvp * vec4(a_position, 1.0);\n"                           \
	"#endif\n"                                                                         \
	"}\n"

#define TREE_FS                                                                            \
	"precision mediump float;\n"                                                       \
	"#ifdef TINT\n"                                                                    \
	"varying vec3 v_tint;\n"                                                           \
	"#define LEAF_COLOR v_tint\n"                                                      \
	"#else\n"                                                                          \
	"uniform vec3 u_color;\n"                                                          \
	"#define LEAF_COLOR u_color\n"                                                     \
	"#endif\n"                                                                         \
	"uniform vec3 u_light;\n"                                                          \
	"uniform bool u_two_sided;\n"                                                      \
	"varying vec3 v_normal;\n"                                                         \
	"#ifdef LIVE\n"                                                                    \
	"varying float v_front;\n"                                                         \
	"#endif\n"                                                                         \
	"void main() {\n"                                                                  \
	/* growing in: nothing past the front */                                           \
	"#ifdef LIVE\n"                                                                    \
	"	if (v_front < 0.0)\n"                                                     \
	"		discard;\n"                                                     \
	"#endif\n"                                                                         \
	"	vec3 n = normalize(v_normal);\n"                                          \
	/* a leaf seen from behind is lit like its front */                                \
	"	if (u_two_sided && !gl_FrontFacing)\n"                                    \
	"		n = -n;\n"                                                       \
	"	float lambert = max(dot(n, u_light), 0.0);\n"                             \
	"	gl_FragColor = vec4(LEAF_COLOR * (0.45 + 0.7 * lambert), 1.0);\n"         \
	"}\n"

const char render_tree_vs[] = TREE_VS;
const char render_tinted_vs[] = "#define TINT\n" TREE_VS;
const char render_tree_fs[] = TREE_FS;
const char render_tinted_fs[] = "#define TINT\n" TREE_FS;
const char render_live_vs[] = "#define LIVE\n" TREE_VS;
const char render_live_tinted_vs[] = "#define LIVE\n#define TINT\n" TREE_VS;
const char render_live_fs[] = "#define LIVE\n" TREE_FS;
const char render_live_tinted_fs[] = "#define LIVE\n#define TINT\n" TREE_FS;
const char render_forest_vs[] = "#define LIVE\n#define FOREST\n" TREE_VS;
const char render_forest_tinted_vs[] = "#define LIVE\n#define FOREST\n#define TINT\n" TREE_VS;

/* Warm paper, like the sheet a child would draw on. */
const float render_paper[3] = { 0.975f, 0.953f, 0.898f };
const float render_bark[3] = { 0.47f, 0.32f, 0.20f };
const float render_vine_stem[3] = { 0.30f, 0.45f, 0.16f };
