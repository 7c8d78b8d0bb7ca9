/* The PLCVEC_* settings (CONTRACT.md, "The environment"): read under their old names too, each
 * PLCVEC_* variable that is no setting named once per process, and PLCVEC_TIMEOUT's one rule. The
 * tables are generated (src/generated/setting_names.c) from plcvec_verify/settings.py. */
#ifndef PLCVEC_SETTINGS_H
#define PLCVEC_SETTINGS_H

#include <stddef.h>

typedef struct plcvec_setting_info {
    const char *name;           /* "PLCVEC_FAMILY" */
    const char *option;         /* the `plcvec verify` option it is the default of */
    const char *meaning;
} plcvec_setting_info;

/* An old name, read as `replacement` (with a warning) from `since` until `until`. */
typedef struct plcvec_old_setting {
    const char *name, *replacement, *since, *until;
} plcvec_old_setting;

extern const plcvec_setting_info plcvec_settings[];
extern const size_t plcvec_n_settings;
/* The largest edit distance at which an unknown PLCVEC_* name is taken for a misspelling. */
extern const size_t plcvec_nearest_distance;
extern const long plcvec_timeout_default_s;
extern const long plcvec_timeout_max_s;
extern const plcvec_old_setting plcvec_old_settings[];
extern const size_t plcvec_n_old_settings;
extern const char *const plcvec_reserved_settings[];           /* NULL-terminated */
extern const char *const plcvec_reserved_setting_prefixes[];   /* NULL-terminated */

/* Print the environment's warnings on stderr, the first time it is called in the process. */
void plcvec_settings_warn(void);
/* What the C library refuses of the environment before a run: PLCVEC_VECTORS (its vectors are
 * compiled in) and a PLCVEC_TIMEOUT against the rule. 0, or -1 with the message in err. */
int plcvec_settings_check(char *err, size_t errlen);
/* PLCVEC_TIMEOUT in ms (10000 when unset), or -1 with CONTRACT.md's message in err. */
long plcvec_settings_timeout_ms(char *err, size_t errlen);

#endif
