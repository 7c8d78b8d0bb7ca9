/* The guards around an implementation's run(): a run must never end green, silent or stuck
 * because of what the implementation did.
 *
 *  - a crash (SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT) inside run() prints the vector being run,
 *    from the signal handler with write(2) alone, and ends the process with status 1;
 *  - exit() called inside run() (any status, 0 included) is caught by an atexit handler, which
 *    names the vector and turns the status into 1: a run ended early is never a pass;
 *  - run() that does not return within the bound (PLCVEC_TIMEOUT, default 10 s) is named by a
 *    watchdog thread, which ends the process with status 1.
 *
 * The guards cost two relaxed stores per vector (the vector being run, and a counter the watchdog
 * reads); nothing is forked and no timer is armed per vector. _exit() and quick_exit() inside
 * run() cannot be seen from the same process. */
/* sigaltstack, nanosleep, clock_gettime: POSIX (the library is built as strict C11). */
#define _XOPEN_SOURCE 700
#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "guard.h"

static _Atomic(const char *) current;           /* the id of the vector inside run(), or NULL */
static atomic_ulong generation;                 /* counts vectors entered: the watchdog sees progress */
static unsigned long entered;                   /* the owner's copy: a plain store, no lock prefix */
static atomic_long timeout_ms;                  /* set by plcvec_guard_install before the watchdog starts */

void plcvec_guard_enter(const char *id)
{
    atomic_store_explicit(&generation, ++entered, memory_order_relaxed);
    atomic_store_explicit(&current, id, memory_order_release);
}

void plcvec_guard_leave(void)
{
    atomic_store_explicit(&current, NULL, memory_order_release);
}

const char *plcvec_guard_current(void)
{
    return atomic_load_explicit(&current, memory_order_acquire);
}

/* ---- writing from a signal handler: write(2) of fixed pieces, nothing else ------------------- */

static void put(const char *s)
{
    size_t n = 0;
    while (s[n])
        n++;
    while (n > 0) {
        ssize_t w = write(STDERR_FILENO, s, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return;
        s += w;
        n -= (size_t)w;
    }
}

static void put_number(long x)
{
    char digits[24];
    int i = (int)sizeof digits - 1;
    digits[i] = '\0';
    do {
        digits[--i] = (char)('0' + x % 10);
        x /= 10;
    } while (x > 0 && i > 0);
    put(digits + i);
}

/* ---- a crash ------------------------------------------------------------------------------- */

static const int crash_signals[] = {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT};
#define N_CRASH (sizeof crash_signals / sizeof crash_signals[0])
static struct sigaction previous[N_CRASH];

static const char *signal_name(int sig)
{
    switch (sig) {
    case SIGSEGV: return "SIGSEGV";
    case SIGBUS: return "SIGBUS";
    case SIGILL: return "SIGILL";
    case SIGFPE: return "SIGFPE";
    default: return "SIGABRT";
    }
}

static void on_crash(int sig)
{
    const char *id = atomic_load_explicit(&current, memory_order_acquire);
    if (id) {
        put("\nERROR ");
        put(id);
        put("\n    the implementation died by signal ");
        put(signal_name(sig));
        put(" while running this vector; the run ends here\nplcvec: the run ended early at ");
        put(id);
        put(" (exit 1)\n");
        _exit(1);
    }
    /* Not inside an implementation: the crash is someone else's; give it back to whoever had it
     * (the default action, a sanitizer, a debugger's handler) and let it happen again. */
    for (size_t i = 0; i < N_CRASH; i++)
        if (crash_signals[i] == sig)
            sigaction(sig, &previous[i], NULL);
    raise(sig);
}

/* ---- exit() inside run() --------------------------------------------------------------------- */

static void at_exit(void)
{
    const char *id = atomic_load_explicit(&current, memory_order_acquire);
    if (!id)
        return;
    fflush(NULL);
    put("\nERROR ");
    put(id);
    put("\n    the implementation ended the process (exit) while running this vector: a run ended early "
        "is not a pass\nplcvec: the run ended early at ");
    put(id);
    put(" (exit 1)\n");
    _exit(1);
}

/* ---- the watchdog ---------------------------------------------------------------------------- */

static long now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (long)t.tv_sec * 1000 + t.tv_nsec / 1000000;
}

static void *watchdog(void *arg)
{
    (void)arg;
    unsigned long seen = 0;
    long since = now_ms();
    for (;;) {
        long bound = atomic_load_explicit(&timeout_ms, memory_order_relaxed);
        long tick = bound / 10 < 1000 ? (bound / 10 > 10 ? bound / 10 : 10) : 1000;
        struct timespec nap = {tick / 1000, (tick % 1000) * 1000000L};
        nanosleep(&nap, NULL);
        unsigned long g = atomic_load_explicit(&generation, memory_order_relaxed);
        const char *id = atomic_load_explicit(&current, memory_order_acquire);
        long now = now_ms();
        if (!id || g != seen) {
            seen = g;
            since = now;
            continue;
        }
        if (now - since >= bound) {
            put("\nERROR ");
            put(id);
            put("\n    no answer within ");
            if (bound % 1000 == 0)
                put_number(bound / 1000);
            else {
                put_number(bound / 1000);
                put(".");
                put_number(bound % 1000 / 100);
            }
            put(" s (PLCVEC_TIMEOUT): the implementation is stuck on this vector; the run ends here\n"
                "plcvec: the run ended early at ");
            put(id);
            put(" (exit 1)\n");
            _exit(1);
        }
    }
    return NULL;
}

/* ---- installing them, once ------------------------------------------------------------------- */

static pthread_once_t once = PTHREAD_ONCE_INIT;
static int installed;

static void install(void)
{
    /* An alternate stack, so that a stack overflow inside run() still reaches the handler. */
    static char alt[65536];
    stack_t ss;
    memset(&ss, 0, sizeof ss);
    ss.ss_sp = alt;
    ss.ss_size = sizeof alt;
    sigaltstack(&ss, NULL);
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_crash;
    sa.sa_flags = SA_ONSTACK;
    sigemptyset(&sa.sa_mask);
    for (size_t i = 0; i < N_CRASH; i++)
        sigaction(crash_signals[i], &sa, &previous[i]);
    atexit(at_exit);
    pthread_t t;
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
    installed = pthread_create(&t, &attr, watchdog, NULL) == 0;
    pthread_attr_destroy(&attr);
}

int plcvec_guard_install(long bound_ms)
{
    atomic_store_explicit(&timeout_ms, bound_ms, memory_order_relaxed);
    pthread_once(&once, install);
    return installed ? 0 : -1;
}
