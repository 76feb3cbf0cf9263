/* SPDX-License-Identifier: MIT */
#include "event.h"

#include <string.h>

static const char *const type_names[] = {
	[EVENT_PROXIMITY_IN] = "proximity-in",
	[EVENT_PROXIMITY_OUT] = "proximity-out",
	[EVENT_TIP_DOWN] = "tip-down",
	[EVENT_TIP_UP] = "tip-up",
	[EVENT_MOTION] = "motion",
	[EVENT_PEN_BUTTON] = "pen-button",
	[EVENT_BUTTON] = "button",
};

static const char *const tool_names[] = {
	[EVENT_TOOL_PEN] = "pen",
	[EVENT_TOOL_ERASER] = "eraser",
};

static const char *const pen_button_names[] = {
	[EVENT_PEN_BUTTON_STYLUS] = "stylus",
	[EVENT_PEN_BUTTON_STYLUS2] = "stylus2",
};

static const char *const button_names[BUTTON_COUNT] = {
	[BUTTON_3D] = "3d",
	[BUTTON_CLONE] = "clone",
	[BUTTON_LEAF] = "leaf",
	[BUTTON_PROPAGATE] = "propagate",
	[BUTTON_UNDO] = "undo",
	[BUTTON_REDO] = "redo",
	[BUTTON_EXPORT] = "export",
	[BUTTON_NEW] = "new",
	[BUTTON_FIXED_COUNT] = "fixed-count",
	[BUTTON_FIXED_SIZE] = "fixed-size",
	[BUTTON_VIEW] = "view",
	[BUTTON_SEASON] = "season",
	[BUTTON_TPL_BLANK] = "tpl-blank",
	[BUTTON_TPL_CHERRY] = "tpl-cherry",
	[BUTTON_TPL_ZELKOVA] = "tpl-zelkova",
	[BUTTON_TPL_HEDGE] = "tpl-hedge",
	[BUTTON_TPL_BALL] = "tpl-ball",
	[BUTTON_TPL_CONE] = "tpl-cone",
	[BUTTON_TPL_PALM] = "tpl-palm",
	[BUTTON_GEN_MORE] = "gen-more",
	[BUTTON_GEN_FEWER] = "gen-fewer",
	[BUTTON_GEN_WIDER] = "gen-wider",
	[BUTTON_GEN_NARROWER] = "gen-narrower",
	[BUTTON_GEN_TALLER] = "gen-taller",
	[BUTTON_GEN_SHORTER] = "gen-shorter",
	[BUTTON_GEN_LEAFIER] = "gen-leafier",
	[BUTTON_GEN_BARER] = "gen-barer",
	[BUTTON_LEAF_DRAWN] = "leaf-drawn",
	[BUTTON_LEAF_ENTIRE] = "leaf-entire",
	[BUTTON_LEAF_HOP] = "leaf-hop",
	[BUTTON_LEAF_MAPLE] = "leaf-maple",
	[BUTTON_VINE] = "vine",
	[BUTTON_GROW] = "grow",
};

#define N(a) (sizeof(a) / sizeof((a)[0]))

static const char *name_of(const char *const *names, unsigned n, int v)
{
	if (v < 0 || (unsigned)v >= n || !names[v])
		return NULL;
	return names[v];
}

static bool from_name(const char *const *names, unsigned n, const char *name, int *v)
{
	for (unsigned i = 0; i < n; i++) {
		if (names[i] && strcmp(names[i], name) == 0) {
			*v = (int)i;
			return true;
		}
	}
	return false;
}

const char *event_type_name(enum event_type type)
{
	return name_of(type_names, N(type_names), (int)type);
}

bool event_type_from_name(const char *name, enum event_type *type)
{
	int v;

	if (!from_name(type_names, N(type_names), name, &v))
		return false;
	*type = (enum event_type)v;
	return true;
}

const char *event_tool_name(enum event_tool tool)
{
	return name_of(tool_names, N(tool_names), (int)tool);
}

bool event_tool_from_name(const char *name, enum event_tool *tool)
{
	int v;

	if (!from_name(tool_names, N(tool_names), name, &v))
		return false;
	*tool = (enum event_tool)v;
	return true;
}

const char *event_pen_button_name(enum event_pen_button button)
{
	return name_of(pen_button_names, N(pen_button_names), (int)button);
}

bool event_pen_button_from_name(const char *name, enum event_pen_button *button)
{
	int v;

	if (!from_name(pen_button_names, N(pen_button_names), name, &v))
		return false;
	*button = (enum event_pen_button)v;
	return true;
}

const char *button_name(enum button button)
{
	return name_of(button_names, N(button_names), (int)button);
}

bool button_from_name(const char *name, enum button *button)
{
	int v;

	if (!from_name(button_names, N(button_names), name, &v))
		return false;
	*button = (enum button)v;
	return true;
}
