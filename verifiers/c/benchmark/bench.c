/* Vectors judged per second by the C runner over the golden set with the C reference, in
 * process, after loading (selecting every vector and building the judge, timed apart). Prints
 * the figures, and last the one-line JSON object `plcvec bench-native` reads. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "reference.h"

#define WARMUP 3
#define PASSES 20

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
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
    double seconds[PASSES];
    for (int pass = 0; pass < WARMUP + PASSES; pass++) {
        double start = now();
        long passed = 0;
        for (long i = 0; i < n; i++)
            passed += plcvec_judge_vector(j, list[i])->status == PLCVEC_PASS;
        double took = now() - start;
        if (passed != n) {
            fprintf(stderr, "bench: the reference passed %ld of %ld vectors\n", passed, n);
            return 1;
        }
        if (pass >= WARMUP)
            seconds[pass - WARMUP] = took;
    }
    qsort(seconds, PASSES, sizeof seconds[0], by_value);
    double median = (seconds[PASSES / 2 - 1] + seconds[PASSES / 2]) / 2;
    printf("C runner with the C reference, in process: %ld vectors, load %.6f s, one pass %.6f s (median of %d), "
           "%.0f vectors/s\n", n, load, median, PASSES, n / median);
    printf("{\"lang\": \"c\", \"vectors\": %ld, \"passes\": %d, \"load_seconds\": %.6f, \"seconds\": %.6f, "
           "\"vectors_per_s\": %.0f, \"note\": \"median of %d passes after %d warm-up\"}\n",
           n, PASSES, load, median, n / median, PASSES, WARMUP);
    plcvec_judge_free(j);
    free(list);
    return 0;
}
