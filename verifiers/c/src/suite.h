/* The compiled-in suite's tables (table.h), and what the library reads of them (suite.c). */
#ifndef PLCVEC_SUITE_H
#define PLCVEC_SUITE_H

#include "table.h"

/* The id `id` became in a `merged` map sorted by the old id, the map followed to its end; NULL
 * when it holds no such id. */
const char *plcvec_merged_follow(const plcvec_merged_id *table, size_t n, const char *id);

#endif
