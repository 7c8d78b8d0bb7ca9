/* The guards around an implementation's run() (guard.c): a crash, an exit() or a hang inside it
 * names the vector and ends the run with status 1. */
#ifndef PLCVEC_GUARD_H
#define PLCVEC_GUARD_H

#include <stddef.h>

/* Install the handlers and the watchdog once per process; set the per-vector bound. -1 when the
 * watchdog thread could not be started (the other guards are in place). */
int plcvec_guard_install(long bound_ms);
/* Around every call of run(): the vector being run. */
void plcvec_guard_enter(const char *id);
void plcvec_guard_leave(void);
const char *plcvec_guard_current(void);

#endif
