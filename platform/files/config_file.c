/* SPDX-License-Identifier: MIT */
/*
 * /etc/edaha/edaha.conf: YAML read with libyaml's document loader (the file is small and
 * capped at CONFIG_MAX_BYTES). docs/config.md describes the keys.
 */
#include "config_file.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

#include "fileio.h"
#include "forest.h"
#include "live.h"
#include "yaml_in.h"
#include "yaml_node.h"

struct cfg_parser {
	struct yaml_in in; /* the file, its text and document (config_parse loads it: an empty
			    * file and null values are allowed here, unlike yaml_in_open) */
	FILE *warn;
	struct config *c;
};


static void warn_unknown(struct cfg_parser *p, const yaml_node_t *key, const char *section)
{
	if (!p->warn)
		return;
	/* the key text is the user's: printed cut short, non-printable bytes as '?' */
	char k[CONFIG_NAME_MAX];
	size_t n = key->data.scalar.length < sizeof(k) - 1 ? key->data.scalar.length : sizeof(k) - 1;

	for (size_t i = 0; i < n; i++) {
		unsigned char ch = key->data.scalar.value[i];

		k[i] = ch >= 0x20 && ch < 0x7f ? (char)ch : '?';
	}
	k[n] = '\0';
	/* a failed warning is no reason to stop the kiosk */
	(void)fprintf(p->warn, "%s:%lu: warning: unknown key \"%s\" in %s, ignored\n", p->in.name,
		      yaml_in_line(&p->in, key), k, section);
}

static bool is_null(const yaml_node_t *n)
{
	const char *s = yaml_node_text(n);

	return yaml_node_plain(n) && s && (!*s || strcmp(s, "~") == 0 || strcmp(s, "null") == 0);
}

static int get_string(struct cfg_parser *p, const yaml_node_t *n, const char *what, char *out,
		      size_t size)
{
	const char *s = yaml_node_text(n);

	if (!s)
		return n->type == YAML_SCALAR_NODE
			       ? yaml_in_fail(&p->in, n, "%s holds a NUL byte", what)
			       : yaml_in_fail(&p->in, n, "expected a string for %s, got %s", what, yaml_node_kind(n));
	if (!*s)
		return yaml_in_fail(&p->in, n, "%s is empty", what);
	if (strlen(s) >= size)
		return yaml_in_fail(&p->in, n, "%s is longer than %zu characters", what, size - 1);
	for (const char *q = s; *q; q++)
		if ((unsigned char)*q < 0x20 || *q == 0x7f)
			return yaml_in_fail(&p->in, n, "%s holds a control character", what);
	memcpy(out, s, strlen(s) + 1);
	return 0;
}

/* A decimal integer within lo..hi: digits with an optional minus, nothing else. */
static int get_int(struct cfg_parser *p, const yaml_node_t *n, const char *what, long lo,
		   long hi, long *v)
{
	const char *s = yaml_node_text(n);
	char *end;
	long x;

	if (!s || !yaml_node_plain(n))
		return yaml_in_fail(&p->in, n, "expected an integer for %s, got %s", what,
			    n->type == YAML_SCALAR_NODE ? "a quoted string" : yaml_node_kind(n));
	if (!((s[0] >= '0' && s[0] <= '9') || (s[0] == '-' && s[1] >= '0' && s[1] <= '9')))
		return yaml_in_fail(&p->in, n, "%s \"%.40s\" is not an integer", what, s);
	errno = 0;
	x = strtol(s, &end, 10);
	if (*end)
		return yaml_in_fail(&p->in, n, "%s \"%.40s\" is not an integer", what, s);
	if (errno == ERANGE || x < lo || x > hi)
		return yaml_in_fail(&p->in, n, "%s %.40s out of range %ld..%ld", what, s, lo, hi);
	*v = x;
	return 0;
}

static int get_bool(struct cfg_parser *p, const yaml_node_t *n, const char *what, bool *v)
{
	const char *s = yaml_node_text(n);

	if (s && yaml_node_plain(n)) {
		if (strcmp(s, "true") == 0 || strcmp(s, "yes") == 0 || strcmp(s, "on") == 0) {
			*v = true;
			return 0;
		}
		if (strcmp(s, "false") == 0 || strcmp(s, "no") == 0 || strcmp(s, "off") == 0) {
			*v = false;
			return 0;
		}
	}
	return yaml_in_fail(&p->in, n, "expected true or false for %s", what);
}

static int get_rotation(struct cfg_parser *p, const yaml_node_t *n, const char *what, int *v)
{
	long x;
	int r = get_int(p, n, what, -100000, 100000, &x);

	if (r < 0)
		return r;
	if (x != 0 && x != 90 && x != 180 && x != 270)
		return yaml_in_fail(&p->in, n, "%s must be 0, 90, 180 or 270, not %ld", what, x);
	*v = (int)x;
	return 0;
}

static int get_fraction(struct cfg_parser *p, const yaml_node_t *n, const char *what, double *v)
{
	const char *s = yaml_node_text(n);
	char *end;
	double x;

	if (!s || !yaml_node_plain(n) || !*s)
		return yaml_in_fail(&p->in, n, "expected a number for %s", what);
	errno = 0;
	x = strtod(s, &end);
	if (*end || errno == ERANGE || !isfinite(x) ||
	    !((s[0] >= '0' && s[0] <= '9') || s[0] == '.' || s[0] == '-'))
		return yaml_in_fail(&p->in, n, "%s \"%.40s\" is not a number", what, s);
	if (x < 0.0 || x > 1.0)
		return yaml_in_fail(&p->in, n, "%s %.40s out of range 0..1", what, s);
	*v = x;
	return 0;
}

/*
 * Calls fn for each pair of the mapping n; duplicate keys are errors, non-scalar keys
 * too. A null value (an empty section) counts as an empty mapping.
 */
typedef int (*pair_fn)(struct cfg_parser *p, const yaml_node_t *key, const char *k,
		       const yaml_node_t *value, void *data);

static int for_each_pair(struct cfg_parser *p, const yaml_node_t *n, const char *what,
			 pair_fn fn, void *data)
{
	yaml_node_pair_t *start, *top;

	if (is_null(n))
		return 0;
	if (n->type != YAML_MAPPING_NODE)
		return yaml_in_fail(&p->in, n, "expected a mapping for %s, got %s", what, yaml_node_kind(n));
	start = n->data.mapping.pairs.start;
	top = n->data.mapping.pairs.top;
	for (yaml_node_pair_t *pair = start; pair < top; pair++) {
		const yaml_node_t *key = yaml_document_get_node(&p->in.doc, pair->key);
		const yaml_node_t *value = yaml_document_get_node(&p->in.doc, pair->value), *other;
		const char *k;
		int r;

		if (!key || !value)
			return yaml_in_fail(&p->in, n, "broken YAML node in %s", what);
		k = yaml_node_text(key);
		if (!k)
			return yaml_in_fail(&p->in, key, "expected a plain key in %s, got %s", what, yaml_node_kind(key));
		other = yaml_node_earlier_key(&p->in.doc, n, pair, k);
		if (other)
			return yaml_in_fail(&p->in, key, "duplicate key \"%.40s\" in %s (first on line %lu)", k,
				    what, yaml_in_line(&p->in, other));
		if ((r = fn(p, key, k, value, data)) < 0)
			return r;
	}
	return 0;
}

/* ---- display -------------------------------------------------------------------- */

/* Digits only (no sign, no space), at most 5 of them; advances *s. */
static bool digits(const char **s, unsigned *v)
{
	unsigned x = 0;
	int n = 0;

	while (**s >= '0' && **s <= '9' && n < 6) {
		x = x * 10 + (unsigned)(**s - '0');
		(*s)++;
		n++;
	}
	*v = x;
	return n > 0 && n <= 5;
}

static int parse_mode(struct cfg_parser *p, const yaml_node_t *n)
{
	const char *s = yaml_node_text(n), *q;
	unsigned w, h, hz = 0;

	if (!s)
		return yaml_in_fail(&p->in, n, "expected a mode like 1920x1080 or 1920x1080@60, got %s", yaml_node_kind(n));
	if (strcmp(s, "preferred") == 0 || strcmp(s, "auto") == 0) {
		p->c->display.mode_w = p->c->display.mode_h = p->c->display.mode_hz = 0;
		return 0;
	}
	q = s;
	if (!digits(&q, &w) || *q++ != 'x' || !digits(&q, &h) ||
	    (*q == '@' && (q++, !digits(&q, &hz))) || *q)
		return yaml_in_fail(&p->in, n, "display mode \"%.40s\" is not WIDTHxHEIGHT[@HZ]", s);
	if (w < 1 || w > 16384 || h < 1 || h > 16384 || hz > 1000)
		return yaml_in_fail(&p->in, n, "display mode \"%.40s\" out of range", s);
	p->c->display.mode_w = (int)w;
	p->c->display.mode_h = (int)h;
	p->c->display.mode_hz = (int)hz;
	return 0;
}

/* "auto" (or null) for card, connector and font means "find one". */
static int get_auto_string(struct cfg_parser *p, const yaml_node_t *n, const char *what,
			   char *out, size_t size)
{
	const char *s = yaml_node_text(n);

	if (is_null(n) || (s && yaml_node_plain(n) && strcmp(s, "auto") == 0)) {
		out[0] = '\0';
		return 0;
	}
	return get_string(p, n, what, out, size);
}

static int display_pair(struct cfg_parser *p, const yaml_node_t *key, const char *k,
			const yaml_node_t *v, void *data)
{
	(void)data;
	if (strcmp(k, "card") == 0)
		return get_auto_string(p, v, "display.card", p->c->display.card,
				       sizeof(p->c->display.card));
	if (strcmp(k, "connector") == 0)
		return get_auto_string(p, v, "display.connector", p->c->display.connector,
				       sizeof(p->c->display.connector));
	if (strcmp(k, "mode") == 0)
		return parse_mode(p, v);
	if (strcmp(k, "rotation") == 0)
		return get_rotation(p, v, "display.rotation", &p->c->display.rotation);
	warn_unknown(p, key, "display");
	return 0;
}

/* ---- input ---------------------------------------------------------------------- */

static int parse_area(struct cfg_parser *p, const yaml_node_t *n)
{
	const char *s = yaml_node_text(n);
	double v[4];
	size_t count;

	if (s && yaml_node_plain(n) && strcmp(s, "fit") == 0) {
		p->c->input.area = CONFIG_AREA_FIT;
		return 0;
	}
	if (s && yaml_node_plain(n) && strcmp(s, "stretch") == 0) {
		p->c->input.area = CONFIG_AREA_STRETCH;
		return 0;
	}
	if (n->type != YAML_SEQUENCE_NODE)
		return yaml_in_fail(&p->in, n, "input.area must be fit, stretch or [left, top, right, bottom]");
	count = (size_t)(n->data.sequence.items.top - n->data.sequence.items.start);
	if (count != 4)
		return yaml_in_fail(&p->in, n, "input.area: expected 4 numbers [left, top, right, bottom], got %zu",
			    count);
	for (size_t i = 0; i < 4; i++) {
		const yaml_node_t *item =
			yaml_document_get_node(&p->in.doc, n->data.sequence.items.start[i]);
		int r;

		if (!item)
			return yaml_in_fail(&p->in, n, "broken YAML node in input.area");
		if ((r = get_fraction(p, item, "input.area", &v[i])) < 0)
			return r;
	}
	if (!(v[2] - v[0] >= 0.01) || !(v[3] - v[1] >= 0.01))
		return yaml_in_fail(&p->in, n, "input.area: right must exceed left and bottom top (by 0.01 at least)");
	p->c->input.area = CONFIG_AREA_RECT;
	memcpy(p->c->input.area_rect, v, sizeof(v));
	return 0;
}

static int input_pair(struct cfg_parser *p, const yaml_node_t *key, const char *k,
		      const yaml_node_t *v, void *data)
{
	(void)data;
	if (strcmp(k, "rotation") == 0)
		return get_rotation(p, v, "input.rotation", &p->c->input.rotation);
	if (strcmp(k, "area") == 0)
		return parse_area(p, v);
	warn_unknown(p, key, "input");
	return 0;
}

/* ---- gpio ----------------------------------------------------------------------- */

struct line_ctx {
	struct config_gpio_line *line;
	bool output;
	const char *what;
	bool have_chip, have_line;
};

static int line_pair(struct cfg_parser *p, const yaml_node_t *key, const char *k,
		     const yaml_node_t *v, void *data)
{
	struct line_ctx *l = data;
	char what[96];

	snprintf(what, sizeof(what), "%s.%s", l->what, k);
	if (strcmp(k, "chip") == 0) {
		l->have_chip = true;
		return get_string(p, v, what, l->line->chip, sizeof(l->line->chip));
	}
	if (strcmp(k, "line") == 0) {
		long off;
		int r;

		l->have_line = true;
		/* a plain integer is an offset; anything else (or quoted) a line name */
		if (yaml_node_plain(v) && yaml_node_text(v) && yaml_node_text(v)[0] >= '0' && yaml_node_text(v)[0] <= '9') {
			if ((r = get_int(p, v, what, 0, 65535, &off)) < 0)
				return r;
			l->line->offset = (int)off;
			l->line->name[0] = '\0';
			return 0;
		}
		l->line->offset = -1;
		return get_string(p, v, what, l->line->name, sizeof(l->line->name));
	}
	if (strcmp(k, "active_low") == 0)
		return get_bool(p, v, what, &l->line->active_low);
	if (strcmp(k, "pull_up") == 0 && !l->output)
		return get_bool(p, v, what, &l->line->pull_up);
	warn_unknown(p, key, l->what);
	return 0;
}

struct lines_ctx {
	struct config_gpio_line *lines;
	bool output;
	const char *section;
};

static int lines_pair(struct cfg_parser *p, const yaml_node_t *key, const char *k,
		      const yaml_node_t *v, void *data)
{
	struct lines_ctx *ls = data;
	char what[64];
	enum button b;
	int r;

	if (!button_from_name(k, &b))
		return yaml_in_fail(&p->in, key, "unknown button \"%.40s\" in %s", k, ls->section);
	if (ls->output && !config_button_is_mode(b))
		return yaml_in_fail(&p->in, key, "%s: only the modes 3d, clone, leaf, propagate and vine have LEDs, "
			    "not %s", ls->section, k);
	snprintf(what, sizeof(what), "%s.%s", ls->section, k);
	struct config_gpio_line *line = &ls->lines[b];
	struct line_ctx l = { .line = line, .output = ls->output, .what = what };

	memset(line, 0, sizeof(*line));
	line->offset = -1;
	line->conf_line = yaml_in_line(&p->in, key);
	if (v->type != YAML_MAPPING_NODE)
		return yaml_in_fail(&p->in, v, "expected a mapping {chip, line, ...} for %s, got %s", what,
			    yaml_node_kind(v));
	if ((r = for_each_pair(p, v, what, line_pair, &l)) < 0)
		return r;
	if (!l.have_chip)
		return yaml_in_fail(&p->in, v, "%s has no chip", what);
	if (!l.have_line)
		return yaml_in_fail(&p->in, v, "%s has no line", what);
	line->set = true;
	return 0;
}

static int gpio_pair(struct cfg_parser *p, const yaml_node_t *key, const char *k,
		     const yaml_node_t *v, void *data)
{
	(void)data;
	if (strcmp(k, "debounce_ms") == 0) {
		long ms;
		int r = get_int(p, v, "gpio.debounce_ms", 0, CONFIG_DEBOUNCE_MS_MAX, &ms);

		if (r == 0)
			p->c->gpio.debounce_ms = (int)ms;
		return r;
	}
	if (strcmp(k, "buttons") == 0) {
		struct lines_ctx ls = { p->c->gpio.buttons, false, "gpio.buttons" };

		return for_each_pair(p, v, "gpio.buttons", lines_pair, &ls);
	}
	if (strcmp(k, "leds") == 0) {
		struct lines_ctx ls = { p->c->gpio.leds, true, "gpio.leds" };

		return for_each_pair(p, v, "gpio.leds", lines_pair, &ls);
	}
	warn_unknown(p, key, "gpio");
	return 0;
}

/* ---- kiosk ---------------------------------------------------------------------- */

static int kiosk_pair(struct cfg_parser *p, const yaml_node_t *key, const char *k,
		      const yaml_node_t *v, void *data)
{
	(void)data;
	if (strcmp(k, "attract_after") == 0) {
		long s;
		int r = get_int(p, v, "kiosk.attract_after", 0, CONFIG_ATTRACT_S_MAX, &s);

		if (r == 0)
			p->c->kiosk.attract_after_s = (int)s;
		return r;
	}
	if (strcmp(k, "export_dir") == 0) {
		const char *s = yaml_node_text(v);
		int r;

		/* no copy kept: the stick is the only place */
		if (is_null(v) || (s && yaml_node_plain(v) && strcmp(s, "none") == 0)) {
			p->c->kiosk.export_dir[0] = '\0';
			return 0;
		}
		r = get_string(p, v, "kiosk.export_dir", p->c->kiosk.export_dir,
			       sizeof(p->c->kiosk.export_dir));

		/* relative to what? the service's working directory is no place for a visitor's tree */
		if (r == 0 && p->c->kiosk.export_dir[0] != '/')
			return yaml_in_fail(&p->in, v, "kiosk.export_dir must be an absolute path");
		return r;
	}
	if (strcmp(k, "state_dir") == 0) {
		int r = get_string(p, v, "kiosk.state_dir", p->c->kiosk.state_dir,
				   sizeof(p->c->kiosk.state_dir));

		if (r == 0 && p->c->kiosk.state_dir[0] != '/')
			return yaml_in_fail(&p->in, v, "kiosk.state_dir must be an absolute path");
		return r;
	}
	if (strcmp(k, "autosave") == 0)
		return get_bool(p, v, "kiosk.autosave", &p->c->kiosk.autosave);
	if (strcmp(k, "reset_after") == 0) {
		long s;
		int r = get_int(p, v, "kiosk.reset_after", 0, CONFIG_RESET_S_MAX, &s);

		if (r == 0)
			p->c->kiosk.reset_after_s = (int)s;
		return r;
	}
	if (strcmp(k, "archive_keep") == 0) {
		long n;
		int r = get_int(p, v, "kiosk.archive_keep", 0, CONFIG_ARCHIVE_KEEP_MAX, &n);

		if (r == 0)
			p->c->kiosk.archive_keep = (int)n;
		return r;
	}
	if (strcmp(k, "wind") == 0)
		return get_fraction(p, v, "kiosk.wind", &p->c->kiosk.wind);
	if (strcmp(k, "grow_in") == 0)
		return get_bool(p, v, "kiosk.grow_in", &p->c->kiosk.grow_in);
	if (strcmp(k, "max_fps") == 0) {
		long n;
		int r = get_int(p, v, "kiosk.max_fps", 1, CONFIG_MAX_FPS_MAX, &n);

		if (r == 0)
			p->c->kiosk.max_fps = (int)n;
		return r;
	}
	warn_unknown(p, key, "kiosk");
	return 0;
}

/* ---- forest --------------------------------------------------------------------- */

/* "HH:MM", 24-hour, local time. */
static int get_time_of_day(struct cfg_parser *p, const yaml_node_t *n, const char *what,
			   int *hour, int *minute)
{
	const char *s = yaml_node_text(n);
	int h, m, used = 0;

	if (!s || sscanf(s, "%2d:%2d%n", &h, &m, &used) != 2 ||
	    s[used] != '\0' || used != 5 || h < 0 || h > 23 || m < 0 || m > 59)
		return yaml_in_fail(&p->in, n, "%s must be a time of day HH:MM (00:00 to 23:59)",
				    what);
	*hour = h;
	*minute = m;
	return 0;
}

static int forest_pair(struct cfg_parser *p, const yaml_node_t *key, const char *k,
		       const yaml_node_t *v, void *data)
{
	(void)data;
	if (strcmp(k, "enabled") == 0)
		return get_bool(p, v, "forest.enabled", &p->c->forest.enabled);
	if (strcmp(k, "max_trees") == 0) {
		long n;
		int r = get_int(p, v, "forest.max_trees", 1, FOREST_MAX_TREES_LIMIT, &n);

		if (r == 0)
			p->c->forest.max_trees = (int)n;
		return r;
	}
	if (strcmp(k, "reset_at") == 0)
		return get_time_of_day(p, v, "forest.reset_at", &p->c->forest.reset_hour,
				       &p->c->forest.reset_minute);
	warn_unknown(p, key, "forest");
	return 0;
}

/* ---- usb ------------------------------------------------------------------------ */

static int usb_pair(struct cfg_parser *p, const yaml_node_t *key, const char *k,
		    const yaml_node_t *v, void *data)
{
	(void)data;
	if (strcmp(k, "enabled") == 0)
		return get_bool(p, v, "usb.enabled", &p->c->usb.enabled);
	if (strcmp(k, "helper_socket") == 0) {
		int r = get_string(p, v, "usb.helper_socket", p->c->usb.helper_socket,
				   sizeof(p->c->usb.helper_socket));

		if (r == 0 && p->c->usb.helper_socket[0] != '/')
			return yaml_in_fail(&p->in, v, "usb.helper_socket must be an absolute path");
		return r;
	}
	warn_unknown(p, key, "usb");
	return 0;
}

/* ---- top level ------------------------------------------------------------------ */

static int top_pair(struct cfg_parser *p, const yaml_node_t *key, const char *k,
		    const yaml_node_t *v, void *data)
{
	(void)data;
	if (strcmp(k, "display") == 0)
		return for_each_pair(p, v, "display", display_pair, NULL);
	if (strcmp(k, "input") == 0)
		return for_each_pair(p, v, "input", input_pair, NULL);
	if (strcmp(k, "gpio") == 0)
		return for_each_pair(p, v, "gpio", gpio_pair, NULL);
	if (strcmp(k, "kiosk") == 0)
		return for_each_pair(p, v, "kiosk", kiosk_pair, NULL);
	if (strcmp(k, "usb") == 0)
		return for_each_pair(p, v, "usb", usb_pair, NULL);
	if (strcmp(k, "forest") == 0)
		return for_each_pair(p, v, "forest", forest_pair, NULL);
	if (strcmp(k, "font") == 0)
		return get_auto_string(p, v, "font", p->c->font, sizeof(p->c->font));
	if (strcmp(k, "language") == 0) {
		const char *s = yaml_node_text(v);

		if (s && yaml_node_plain(v) && strcmp(s, "en") == 0)
			p->c->language = CONFIG_LANG_EN;
		else if (s && yaml_node_plain(v) && strcmp(s, "ja") == 0)
			p->c->language = CONFIG_LANG_JA;
		else
			return yaml_in_fail(&p->in, v, "language must be en or ja");
		return 0;
	}
	warn_unknown(p, key, "the top level");
	return 0;
}

bool config_button_is_mode(enum button b)
{
	return b == BUTTON_3D || b == BUTTON_CLONE || b == BUTTON_LEAF || b == BUTTON_PROPAGATE ||
	       b == BUTTON_VINE;
}

void config_defaults(struct config *c)
{
	memset(c, 0, sizeof(*c));
	c->input.area = CONFIG_AREA_FIT;
	c->input.area_rect[2] = c->input.area_rect[3] = 1.0;
	c->gpio.debounce_ms = CONFIG_DEBOUNCE_MS_DEFAULT;
	for (int b = 0; b < BUTTON_COUNT; b++)
		c->gpio.buttons[b].offset = c->gpio.leds[b].offset = -1;
	c->language = CONFIG_LANG_EN;
	c->kiosk.attract_after_s = CONFIG_ATTRACT_S_DEFAULT;
	memcpy(c->kiosk.export_dir, CONFIG_EXPORT_DIR_DEFAULT, sizeof(CONFIG_EXPORT_DIR_DEFAULT));
	c->usb.enabled = true;
	memcpy(c->usb.helper_socket, CONFIG_USB_SOCKET_DEFAULT, sizeof(CONFIG_USB_SOCKET_DEFAULT));
	memcpy(c->kiosk.state_dir, CONFIG_STATE_DIR_DEFAULT, sizeof(CONFIG_STATE_DIR_DEFAULT));
	c->kiosk.reset_after_s = CONFIG_RESET_S_DEFAULT;
	c->kiosk.autosave = true;
	c->kiosk.archive_keep = CONFIG_ARCHIVE_KEEP_DEFAULT;
	c->kiosk.wind = LIVE_WIND_DEFAULT_STRENGTH;
	c->kiosk.grow_in = true;
	c->kiosk.max_fps = CONFIG_MAX_FPS_DEFAULT;
	c->forest.enabled = true;
	c->forest.max_trees = FOREST_MAX_TREES_DEFAULT;
	c->forest.reset_hour = 4;
	c->forest.reset_minute = 0;
}

static int yaml_fail(struct cfg_parser *p, const yaml_parser_t *y, const char *data,
		     size_t len)
{
	return yaml_node_parse_error(p->in.err, p->in.name, 0, y, data, len);
}

int config_parse(const char *data, size_t len, const char *name, struct config *c, FILE *warn,
		 struct error *err)
{
	struct cfg_parser p = {
		.in = { .name = name, .err = err, .data = data, .len = len }, .warn = warn
	};
	struct config tmp;
	yaml_parser_t y;
	yaml_node_t *root;
	int r;

	config_defaults(c);
	if (len > CONFIG_MAX_BYTES)
		return error_at(err, -EINVAL, name, 0, "larger than %d bytes", CONFIG_MAX_BYTES);
	config_defaults(&tmp);
	p.c = &tmp;
	if (!yaml_parser_initialize(&y))
		return error_at(err, -ENOMEM, name, 0, "out of memory");
	yaml_parser_set_input_string(&y, (const unsigned char *)data, len);
	if (!yaml_parser_load(&y, &p.in.doc)) {
		r = yaml_fail(&p, &y, data, len);
		yaml_parser_delete(&y);
		return r;
	}
	root = yaml_document_get_root_node(&p.in.doc);
	if (root) { /* no root: an empty file, the defaults */
		yaml_document_t second;

		/* one document only: a second one is probably a mistake */
		if (!yaml_parser_load(&y, &second)) {
			r = yaml_fail(&p, &y, data, len);
			goto out;
		}
		bool more = yaml_document_get_root_node(&second) != NULL;
		unsigned long at = more ? yaml_in_line(&p.in, yaml_document_get_root_node(&second)) : 0;

		yaml_document_delete(&second);
		if (more) {
			r = error_at(err, -EINVAL, name, at, "a second YAML document; one is expected");
			goto out;
		}
		if (is_null(root))
			r = 0;
		else if (root->type != YAML_MAPPING_NODE)
			r = yaml_in_fail(&p.in, root, "expected a mapping (display:, input:, gpio:, ...) at the top, got %s",
				 yaml_node_kind(root));
		else
			r = for_each_pair(&p, root, "the top level", top_pair, NULL);
	} else {
		r = 0;
	}
out:
	yaml_document_delete(&p.in.doc);
	yaml_parser_delete(&y);
	if (r == 0)
		*c = tmp;
	return r;
}

int config_load(const char *path, struct config *c, FILE *warn, struct error *err)
{
	char *data;
	size_t len;
	int r;

	config_defaults(c);
	r = fileio_read_all(path, CONFIG_MAX_BYTES, &data, &len, err);
	if (r == -ENOENT)
		return 0;
	if (r < 0)
		return r;
	r = config_parse(data, len, path, c, warn, err);
	free(data);
	return r;
}
