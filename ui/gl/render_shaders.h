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

/* The paper behind every picture. */
extern const float render_paper[3];

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
