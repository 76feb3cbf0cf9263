/* SPDX-License-Identifier: MIT */
#pragma once

#include <json-c/json.h>

#include "buf.h"

/*
 * Building JSON with json-c so that allocation failure propagates as NULL: a failing add
 * frees the parent too, so one check on the root covers the whole document and nothing
 * leaks. Shared by the exporters.
 */
struct json_object *json_out_set(struct json_object *obj, const char *key, struct json_object *val);
struct json_object *json_out_push(struct json_object *arr, struct json_object *val);

/*
 * Serialises root compactly and appends it to out (plus `suffix`, may be NULL).
 * Returns 0 or -ENOMEM; on failure out is as it was. Does not free root.
 */
int json_out_append(struct json_object *root, const char *suffix, struct buf *out);
