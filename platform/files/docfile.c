/* SPDX-License-Identifier: MIT */
#include "docfile.h"

#include <stdlib.h>

#include "fileio.h"

int docfile_read(const char *path, struct doc *doc, struct error *err)
{
	char *data;
	size_t len;
	int ret = fileio_read_all(path, DOC_MAX_FILE_BYTES, &data, &len, err);

	if (ret < 0)
		return ret;
	ret = doc_parse(data, len, path, doc, err);
	free(data);
	return ret;
}
