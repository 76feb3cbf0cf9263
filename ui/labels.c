/* SPDX-License-Identifier: MIT */
#include "labels.h"

#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

#define NLANGS 2

/*
 * English: the physical buttons' names where a child knows the word, plain words where
 * not ("spread" for propagate, "save" for export: what it does for them).
 * Japanese: hiragana; undo/redo as "back"/"forward" (もどす/すすめる) rather than
 * やりなおし, which a child reads as "start over", the new button's job.
 *
 * The New strip's cards name their trees as a child would: the blank one "draw" (かく),
 * the shrubs by their shapes (まる, さんかく). The parameter buttons are pairs in the same
 * form (wider/narrower, ひろく/せまく); the Japanese branch and leaf pairs carry a plus and
 * a minus sign (U+2212), not a hyphen, which after kana reads as the long vowel ー.
 */
static const char *const button_words[BUTTON_COUNT][NLANGS] = {
	[BUTTON_3D] = { "3D", "りったい" },
	[BUTTON_CLONE] = { "Clone", "ふやす" },
	[BUTTON_LEAF] = { "Leaf", "はっぱ" },
	[BUTTON_PROPAGATE] = { "Spread", "ひろげる" },
	[BUTTON_UNDO] = { "Undo", "もどす" },
	[BUTTON_REDO] = { "Redo", "すすめる" },
	[BUTTON_EXPORT] = { "Save", "ほぞん" },
	[BUTTON_NEW] = { "New", "あたらしく" },
	[BUTTON_FIXED_COUNT] = { "Count", "かず" },
	[BUTTON_FIXED_SIZE] = { "Size", "おおきさ" },
	[BUTTON_VIEW] = { "Front", "まえ" },
	[BUTTON_SEASON] = { "Season", "きせつ" },
	[BUTTON_TPL_BLANK] = { "Draw", "かく" },
	[BUTTON_TPL_CHERRY] = { "Cherry", "さくら" },
	[BUTTON_TPL_ZELKOVA] = { "Zelkova", "けやき" },
	[BUTTON_TPL_HEDGE] = { "Hedge", "いけがき" },
	[BUTTON_TPL_BALL] = { "Ball", "まる" },
	[BUTTON_TPL_CONE] = { "Cone", "さんかく" },
	[BUTTON_TPL_PALM] = { "Palm", "やし" },
	[BUTTON_GEN_MORE] = { "More", "えだ+" },
	[BUTTON_GEN_FEWER] = { "Fewer", "えだ\u2212" },
	[BUTTON_GEN_WIDER] = { "Wider", "ひろく" },
	[BUTTON_GEN_NARROWER] = { "Narrower", "せまく" },
	[BUTTON_GEN_TALLER] = { "Taller", "たかく" },
	[BUTTON_GEN_SHORTER] = { "Shorter", "ひくく" },
	[BUTTON_GEN_LEAFIER] = { "Leafier", "はっぱ+" },
	[BUTTON_GEN_BARER] = { "Barer", "はっぱ\u2212" },
	[BUTTON_LEAF_DRAWN] = { "Mine", "じぶんの" },
	[BUTTON_LEAF_ENTIRE] = { "Plain", "まるい" },
	[BUTTON_LEAF_HOP] = { "Hop", "ほっぷ" },
	[BUTTON_LEAF_MAPLE] = { "Maple", "もみじ" },
	[BUTTON_VINE] = { "Vine", "つる" },
	[BUTTON_GROW] = { "Grow", "そだてる" },
};

/*
 * The USB stick is "the stick" in English, "USB" in Japanese (what children there call
 * it); each message says what happened and, where there is one, what to do next.
 */
static const char *const status_words[APP_STATUS_COUNT][NLANGS] = {
	[APP_STATUS_SAVED] = { "Saved!", "ほぞんしたよ!" },
	[APP_STATUS_SAVE_FAILED] = { "Could not save", "ほぞん できなかったよ" },
	[APP_STATUS_SAVING] = { "Saving... leave the stick in", "ほぞんちゅう… USBを ぬかないでね" },
	[APP_STATUS_SAVED_USB] = { "Saved! You can take the stick out",
				   "ほぞんしたよ! USBを ぬいて いいよ" },
	[APP_STATUS_NO_STICK] = { "Put in a USB stick to take your tree home",
				  "USBを さしてね。木を もってかえれるよ" },
	[APP_STATUS_STICK_PULLED] = { "The stick came out too soon. Put it back and save again",
				      "USBが ぬけちゃった。さして もういちど ほぞんしてね" },
	[APP_STATUS_STICK_FULL] = { "The stick is full", "USBが いっぱいだよ" },
	[APP_STATUS_STICK_LOCKED] = { "The stick is locked", "USBに かきこめないよ" },
	[APP_STATUS_STICK_UNUSABLE] = { "This stick cannot be used", "この USBは つかえないよ" },
	[APP_STATUS_STICK_READY] = { "Stick ready: press Save", "USB OK! 「ほぞん」を おしてね" },
	[APP_STATUS_VINE_TAP] = { "Tap the ground by the trunk to plant a vine",
				  "みきの ねもとを タップして つるを うえよう" },
	[APP_STATUS_VINE_WHERE] = { "Tap closer to the bottom of the trunk",
				    "みきの ねもとの ちかくを タップしてね" },
	[APP_STATUS_GROWING] = { "Growing... a year older", "そだってるよ… 1ねん たつよ" },
	[APP_STATUS_VINE_FULL] = { "This tree has all the vines it can hold",
				   "この木には もう つるが いっぱいだよ" },
	/* '#': the number (labels_format); "ばん" is how a child counts places in a line */
	[APP_STATUS_IN_FOREST] = { "Your tree is No. # in today's forest",
				   "きみの 木は きょうの もりの #ばん だよ" },
};

static const char *const attract_words[NLANGS] = {
	"Draw a tree with the pen!",
	"ペンで 木を かいてみよう!",
};

static int index_of(enum render_lang lang)
{
	return lang == RENDER_LANG_JA ? 1 : 0;
}

const char *labels_button(enum button b, enum render_lang lang)
{
	if (b < 0 || b >= BUTTON_COUNT)
		return "";
	return button_words[b][index_of(lang)];
}

const char *labels_status(enum app_status s, enum render_lang lang)
{
	if (s <= APP_STATUS_NONE || s >= APP_STATUS_COUNT)
		return NULL;
	return status_words[s][index_of(lang)];
}

int labels_format(enum app_status s, enum render_lang lang, uint64_t number, char *out,
		  size_t size)
{
	const char *w = labels_status(s, lang), *hash;
	int n;

	if (!w || !size)
		return -EINVAL;
	hash = strchr(w, '#');
	if (hash)
		n = snprintf(out, size, "%.*s%" PRIu64 "%s", (int)(hash - w), w, number, hash + 1);
	else
		n = snprintf(out, size, "%s", w);
	return n < 0 || (size_t)n >= size ? -ENOSPC : 0;
}

const char *labels_attract(enum render_lang lang)
{
	return attract_words[index_of(lang)];
}

const char *labels_nth(enum render_lang lang, size_t i)
{
	if (i < BUTTON_COUNT)
		return labels_button((enum button)i, lang);
	i -= BUTTON_COUNT;
	if (i + 1 < APP_STATUS_COUNT)
		return labels_status((enum app_status)(i + 1), lang);
	i -= APP_STATUS_COUNT - 1;
	return i == 0 ? labels_attract(lang) : NULL;
}
