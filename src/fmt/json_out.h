/* SPDX-License-Identifier: MIT */
#pragma once

#include <json-c/json.h>

#include "buf.h"

/*
 * Building JSON with json-c so that allocation failure propagates as NULL: a failing add
 * frees the parent too, so one check on the root covers the whole document and nothing
 * leaks. Shared by the exporters.
 */
/* key must outlive obj (a string literal): obj keeps the pointer, not a copy. */
struct json_object *json_out_set(struct json_object *obj, const char *key, struct json_object *val);
struct json_object *json_out_push(struct json_object *arr, struct json_object *val);

/*
 * A coordinate or length, rounded to micrometres and printed as short as it goes
 * (numfmt_micro): 0.1 not 0.10000000000000001, 2 not 2.000000, 0 not -0. JSON has no NaN
 * or infinity; the models never hold one, and a 0 keeps the file readable if one ever did.
 * NULL without memory.
 */
struct json_object *json_out_num(double v);

/*
 * Serialises root compactly and appends it to out (plus `suffix`, may be NULL).
 * Returns 0 or -ENOMEM; on failure out is as it was. Does not free root.
 */
int json_out_append(struct json_object *root, const char *suffix, struct buf *out);
