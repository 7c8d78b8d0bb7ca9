/* The reference passes every vector under the combinations of alternatives of its family's
 * interpretations (declaring the combination it follows), judged by the library's runner: every
 * combination while there are at most 1,024; past that (HOUR's eleven interpretations have tens of
 * thousands) a pairwise covering set, every alternative of each interpretation beside every
 * alternative of each other in some combination, as the Python tests run them
 * (tests/combinations.py); and, in either case, each vector under each combination it offers an
 * expectation for. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reference.h"

#define PRODUCT_BOUND 1024

typedef struct tally {
    size_t runs, failures, combinations;
} tally;

/* The vectors of family f (or v alone) judged with the reference following pick[k] for interps[k]
 * (the others at their default). */
static int judge_under(int f, const plcvec_vector *only, const int *interps, const int *pick, int n, tally *t)
{
    static plcvec_reference ref;
    plcvec_reference_init(&ref);
    for (int k = 0; k < n; k++)
        ref.declared[interps[k]] = ref.machine.follows[interps[k]] = (uint8_t)pick[k];
    plcvec_impl impl = plcvec_reference_impl(&ref);
    char err[256];
    plcvec_judge *j = plcvec_judge_new(&impl, err, sizeof err);
    if (!j) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    t->combinations++;
    for (size_t i = 0; i < plcvec_count(); i++) {
        const plcvec_vector *v = plcvec_at(i);
        if ((int)v->family != f || (only && v != only))
            continue;
        const plcvec_verdict *vd = plcvec_judge_vector(j, v);
        t->runs++;
        if (vd->status != PLCVEC_PASS && t->failures++ < 10)
            plcvec_print_verdict(stdout, vd);
    }
    plcvec_judge_free(j);
    return 0;
}

/* Every combination: an odometer over the alternatives. */
static int every_combination(int f, const int *interps, int n, tally *t)
{
    int pick[PLCVEC_INTERPRETATION_COUNT] = {0};
    for (;;) {
        if (judge_under(f, NULL, interps, pick, n, t) != 0)
            return -1;
        int k = 0;
        while (k < n && ++pick[k] == plcvec_interpretations[interps[k]].n_alternatives)
            pick[k++] = 0;
        if (k == n)
            return 0;
    }
}

/* Pairs (k, a) with (m, b), k < m, not yet in a combination run: covered[k][m][a][b]. */
#define MAX_ALTERNATIVES 8
typedef uint8_t pairs[PLCVEC_INTERPRETATION_COUNT][PLCVEC_INTERPRETATION_COUNT][MAX_ALTERNATIVES][MAX_ALTERNATIVES];

static int size_of(const int *interps, int k)
{
    return plcvec_interpretations[interps[k]].n_alternatives;
}

/* How many pairs of `row` (set where >= 0) with alternative a of k would be new. */
static int gain(pairs *covered, const int *row, int n, int k, int a)
{
    int g = 0;
    for (int m = 0; m < n; m++)
        if (m != k && row[m] >= 0)
            g += !(m < k ? (*covered)[m][k][row[m]][a] : (*covered)[k][m][a][row[m]]);
    return g;
}

/* A pairwise covering set, built greedily and deterministically: each combination starts from the
 * first pair not yet covered, each other interpretation taking the alternative that covers the most
 * new pairs with those already set (the first on a tie). */
static int pairwise(int f, const int *interps, int n, tally *t)
{
    static pairs covered;
    memset(covered, 0, sizeof covered);
    for (;;) {
        int row[PLCVEC_INTERPRETATION_COUNT], found = 0;
        for (int k = 0; k < n; k++)
            row[k] = -1;
        for (int k = 0; k < n && !found; k++)
            for (int m = k + 1; m < n && !found; m++)
                for (int a = 0; a < size_of(interps, k) && !found; a++)
                    for (int b = 0; b < size_of(interps, m) && !found; b++)
                        if (!covered[k][m][a][b])
                            row[k] = a, row[m] = b, found = 1;
        if (!found)
            return 0;
        for (int k = 0; k < n; k++) {
            int best = 0, best_gain = -1;
            for (int a = 0; row[k] < 0 && a < size_of(interps, k); a++) {
                int g = gain(&covered, row, n, k, a);
                if (g > best_gain)
                    best = a, best_gain = g;
            }
            if (row[k] < 0)
                row[k] = best;
        }
        for (int k = 0; k < n; k++)
            for (int m = k + 1; m < n; m++)
                covered[k][m][row[k]][row[m]] = 1;
        if (judge_under(f, NULL, interps, row, n, t) != 0)
            return -1;
    }
}

/* Each vector of family f under each combination it offers an expectation for. */
static int offered_combinations(int f, const int *interps, int n, tally *t)
{
    for (size_t i = 0; i < plcvec_count(); i++) {
        const plcvec_vector *v = plcvec_at(i);
        if ((int)v->family != f)
            continue;
        for (size_t o = 0; o <= v->n_alternatives; o++) {
            int pick[PLCVEC_INTERPRETATION_COUNT];
            for (int k = 0; k < n; k++) {
                int a = o ? -1 : plcvec_interpretations[interps[k]].default_alternative;
                for (size_t c = 0; o && c < v->alternatives[o - 1].n_choices; c++)
                    if (v->alternatives[o - 1].choices[c].interpretation == interps[k])
                        a = v->alternatives[o - 1].choices[c].alternative;
                pick[k] = a >= 0 ? a : plcvec_interpretations[interps[k]].default_alternative;
            }
            if (judge_under(f, v, interps, pick, n, t) != 0)
                return -1;
        }
    }
    return 0;
}

int main(void)
{
    tally t = {0, 0, 0};
    for (int f = 0; f < PLCVEC_FAMILY_COUNT; f++) {
        int interps[PLCVEC_INTERPRETATION_COUNT], n = 0;
        size_t product = 1;
        for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
            if (plcvec_interpretations[i].families >> f & 1) {
                interps[n++] = i;
                product *= plcvec_interpretations[i].n_alternatives;
                if (plcvec_interpretations[i].n_alternatives > MAX_ALTERNATIVES)
                    return fprintf(stderr, "%s has more than %d alternatives\n", plcvec_interpretations[i].id, MAX_ALTERNATIVES), 2;
            }
        int rc = product <= PRODUCT_BOUND ? every_combination(f, interps, n, &t) : pairwise(f, interps, n, &t);
        if (rc != 0 || (product > PRODUCT_BOUND && offered_combinations(f, interps, n, &t) != 0))
            return 2;
        printf("%s: %s\n", plcvec_family_names[f], product <= PRODUCT_BOUND ? "every combination" : "a pairwise set and each vector's own");
    }
    printf("reference: %zu vector runs over %zu combinations of alternatives, %zu not passed\n", t.runs, t.combinations,
           t.failures);
    return t.failures || t.runs < plcvec_count() ? 1 : 0;
}
