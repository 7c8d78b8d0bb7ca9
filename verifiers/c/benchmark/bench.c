/* Vectors judged per second by the C runner over the golden set with the C reference, in
 * process, after loading (selecting every vector and building the judge, timed apart). Prints
 * the figures, and last the one-line JSON object `plcvec bench-native` reads. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "reference.h"

#define WARMUP 3
#define PASSES 50

static double clock_s(clockid_t which)
{
    struct timespec ts;
    clock_gettime(which, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static double now(void)
{
    return clock_s(CLOCK_MONOTONIC);
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(void)
{
    static plcvec_reference ref;
    plcvec_reference_init(&ref);
    plcvec_impl impl = plcvec_reference_impl(&ref);
    char err[256];
    double t0 = now();
    const plcvec_vector **list = NULL;
    long n = plcvec_select(NULL, &list, err, sizeof err);
    plcvec_judge *j = n > 0 ? plcvec_judge_new(&impl, err, sizeof err) : NULL;
    double load = now() - t0;
    if (!j) {
        fprintf(stderr, "bench: %s\n", n > 0 ? err : "no vectors");
        return 1;
    }
    /* Wall-clock time is the figure (as the Python one beside it); the CPU time of the process is
     * printed too, since on a shared machine other processes stretch the wall clock. */
    double seconds[PASSES], cpu[PASSES];
    for (int pass = 0; pass < WARMUP + PASSES; pass++) {
        double start = now(), cpu_start = clock_s(CLOCK_PROCESS_CPUTIME_ID);
        long passed = 0;
        for (long i = 0; i < n; i++)
            passed += plcvec_judge_vector(j, list[i])->status == PLCVEC_PASS;
        double took = now() - start, cpu_took = clock_s(CLOCK_PROCESS_CPUTIME_ID) - cpu_start;
        if (passed != n) {
            fprintf(stderr, "bench: the reference passed %ld of %ld vectors\n", passed, n);
            return 1;
        }
        if (pass >= WARMUP) {
            seconds[pass - WARMUP] = took;
            cpu[pass - WARMUP] = cpu_took;
        }
    }
    qsort(seconds, PASSES, sizeof seconds[0], by_value);
    qsort(cpu, PASSES, sizeof cpu[0], by_value);
    double median = (seconds[PASSES / 2 - 1] + seconds[PASSES / 2]) / 2;
    double cpu_median = (cpu[PASSES / 2 - 1] + cpu[PASSES / 2]) / 2;
    printf("C runner with the C reference, in process: %ld vectors, load %.6f s, one pass %.6f s (median of %d), "
           "%.0f vectors/s; fastest pass %.0f vectors/s; CPU time %.0f vectors/s\n",
           n, load, median, PASSES, n / median, n / seconds[0], n / cpu_median);
    printf("{\"lang\": \"c\", \"vectors\": %ld, \"passes\": %d, \"load_seconds\": %.6f, \"seconds\": %.6f, "
           "\"vectors_per_s\": %.0f, \"note\": \"median of %d passes after %d warm-up\"}\n",
           n, PASSES, load, median, n / median, PASSES, WARMUP);
    plcvec_judge_free(j);
    free(list);
    return 0;
}
