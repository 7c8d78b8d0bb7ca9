/* The inference (TEXT.md, "The inference"): starting from the alternatives followed, each
 * interpretation in id order takes, of its alternatives in the order the vector files list them,
 * the first that lets strictly the most judged vectors pass, every other interpretation as it
 * stands, until a round changes nothing; first among the alternatives that judge every device,
 * then among all. A vector passes under a combination when its answer has no
 * problem against the expectation offered for it (a failed answer), or when that expectation
 * judges alike what the followed one judges (an answer that passed). */
#include <stdlib.h>
#include <string.h>

#include "expect.h"
#include "infer.h"

/* The offered expectation whose alternatives for v's interpretations are `combo`'s (0: the vector's
 * own, o: alternatives[o - 1]); -1 when v offers none. */
static long offered_for(const plcvec_vector *v, const uint8_t *combo)
{
    for (size_t o = 0; o <= v->n_alternatives; o++) {
        const plcvec_alternative *entry = o ? &v->alternatives[o - 1] : NULL;
        if (entry && entry->n_expect != v->n_steps)
            continue;
        size_t i = 0;
        while (i < v->n_interpretations && plcvec_expect_offered(entry, v->interpretations[i]) == combo[v->interpretations[i]])
            i++;
        if (i == v->n_interpretations)
            return (long)o;
    }
    return -1;
}

static int passes_under(const plcvec_judged *r, const uint8_t *combo)
{
    long o = offered_for(r->v, combo);
    return o >= 0 && o < 64 && (r->passes >> o & 1);
}

static int touches(const plcvec_vector *v, int interp)
{
    for (size_t i = 0; i < v->n_interpretations; i++)
        if (v->interpretations[i] == interp)
            return 1;
    return 0;
}

/* A vector that passed: the offered expectations under which it passes too. An interpretation no
 * failed answer touches never moves, so a vector touching only such ones needs only the followed. */
static int passing_offers(plcvec_judged *r, const uint8_t *followed, const uint8_t *movable)
{
    long f = offered_for(r->v, followed);
    r->passes = f >= 0 && f < 64 ? UINT64_C(1) << f : 0;
    int moves = 0;
    for (size_t i = 0; i < r->v->n_interpretations; i++)
        moves |= movable[r->v->interpretations[i]];
    if (!moves || f < 0)
        return 0;
    const plcvec_alternative *mine = f ? &r->v->alternatives[f - 1] : NULL;
    for (size_t o = 0; o <= r->v->n_alternatives && o < 64; o++) {
        const plcvec_alternative *entry = o ? &r->v->alternatives[o - 1] : NULL;
        if ((long)o == f || (entry && entry->n_expect != r->v->n_steps))
            continue;
        int same = plcvec_expect_same(r->v, entry, mine);
        if (same < 0)
            return -1;
        if (same)
            r->passes |= UINT64_C(1) << o;
    }
    return 0;
}

static size_t score(const plcvec_judged *judged, size_t n, const uint8_t *combo, int interp)
{
    size_t total = 0;
    for (size_t i = 0; i < n; i++)
        total += judged[i].answer != PLCVEC_ANSWER_NONE && touches(judged[i].v, interp) && passes_under(&judged[i], combo);
    return total;
}

/* The alternatives (bit a of [i]) some vector of the suite leaves devices unjudged under: an entry
 * of its `alternatives` whose unjudged map names i, and whose choice for i is a. Worked out once. */
static const uint32_t *unjudging(void)
{
    static uint32_t leaves[PLCVEC_INTERPRETATION_COUNT];
    static int done;
    for (size_t k = 0; !done && k < plcvec_count(); k++) {
        const plcvec_vector *v = plcvec_at(k);
        for (size_t a = 0; a < v->n_alternatives; a++)
            for (size_t u = 0; u < v->alternatives[a].n_unjudged; u++) {
                int i = v->alternatives[a].unjudged[u].interpretation, alt = plcvec_expect_offered(&v->alternatives[a], i);
                if (alt >= 0 && alt < 32)
                    leaves[i] |= UINT32_C(1) << alt;
            }
    }
    done = 1;
    return leaves;
}

/* One round over the interpretations in id order, each taking only alternatives of `allowed[i]`
 * (bit a); whether it changed the choice. */
static int round_of_choices(const plcvec_judged *judged, size_t n, const int *order, int n_order, uint8_t *choice,
                            const uint32_t *allowed)
{
    int changed = 0;
    for (int k = 0; k < n_order; k++) {
        int i = order[k], keep = choice[i], best_alt = -1;
        size_t current = score(judged, n, choice, i), best = 0;
        for (int a = 0; a < plcvec_interpretations[i].n_alternatives; a++) {
            if (a == keep || !(allowed[i] >> a & 1))
                continue;
            choice[i] = (uint8_t)a;
            size_t sc = score(judged, n, choice, i);
            if (best_alt < 0 || sc > best)
                best = sc, best_alt = a;
        }
        choice[i] = (uint8_t)keep;
        if (best_alt >= 0 && best > current) {
            choice[i] = (uint8_t)best_alt;
            changed = 1;
        }
    }
    return changed;
}

static int by_interpretation_id(const void *a, const void *b)
{
    return strcmp(plcvec_interpretations[*(const int *)a].id, plcvec_interpretations[*(const int *)b].id);
}

int plcvec_infer(plcvec_judged *judged, size_t n, const uint8_t *followed, plcvec_inference *inf)
{
    uint8_t movable[PLCVEC_INTERPRETATION_COUNT] = {0}, touched[PLCVEC_INTERPRETATION_COUNT] = {0};
    for (size_t r = 0; r < n; r++)
        for (size_t k = 0; judged[r].answer != PLCVEC_ANSWER_NONE && k < judged[r].v->n_interpretations; k++) {
            touched[judged[r].v->interpretations[k]] = 1;
            movable[judged[r].v->interpretations[k]] |= judged[r].answer == PLCVEC_ANSWER_FAILED;
        }
    for (size_t r = 0; r < n; r++)
        if (judged[r].answer == PLCVEC_ANSWER_PASSED && passing_offers(&judged[r], followed, movable) != 0)
            return -1;
    int order[PLCVEC_INTERPRETATION_COUNT], n_order = 0;
    for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
        if (touched[i])
            order[n_order++] = i;
    qsort(order, (size_t)n_order, sizeof *order, by_interpretation_id);
    memcpy(inf->followed, followed, sizeof inf->followed);
    memcpy(inf->choice, followed, sizeof inf->choice);
    /* Twice (TEXT.md, step 4): first without the alternatives that leave devices unjudged, which
     * explain any answer there and so would take another reading's failures; then, from where the
     * first ended, with every alternative. */
    uint32_t judging[PLCVEC_INTERPRETATION_COUNT], every[PLCVEC_INTERPRETATION_COUNT];
    const uint32_t *leaves = unjudging();
    for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
        every[i] = UINT32_MAX, judging[i] = ~leaves[i];
    while (round_of_choices(judged, n, order, n_order, inf->choice, judging))
        ;
    while (round_of_choices(judged, n, order, n_order, inf->choice, every))
        ;
    inf->broken = 0;
    for (size_t r = 0; r < n; r++)
        inf->broken += plcvec_broken(inf, &judged[r]);
    return 0;
}

int plcvec_broken(const plcvec_inference *inf, const plcvec_judged *r)
{
    return r->status == PLCVEC_PASS && r->answer == PLCVEC_ANSWER_PASSED && !passes_under(r, inf->choice);
}

int plcvec_explained(const plcvec_inference *inf, const plcvec_judged *r)
{
    return r->answer == PLCVEC_ANSWER_FAILED && passes_under(r, inf->choice);
}

/* The next subset of `size` positions of `n` in lexicographic order (itertools.combinations); 0
 * after the last. */
static int next_subset(int *pick, int size, int n)
{
    int q = size - 1;
    while (q >= 0 && pick[q] == n - size + q)
        q--;
    if (q < 0)
        return 0;
    pick[q]++;
    for (int w = q + 1; w < size; w++)
        pick[w] = pick[w - 1] + 1;
    return 1;
}

int plcvec_smallest_change(const plcvec_inference *inf, const plcvec_judged *r, int *out)
{
    int differ[PLCVEC_INTERPRETATION_COUNT], nd = 0;
    for (size_t k = 0; k < r->v->n_interpretations; k++) {
        int i = r->v->interpretations[k];
        if (inf->choice[i] != inf->followed[i])
            differ[nd++] = i;
    }
    qsort(differ, (size_t)nd, sizeof *differ, by_interpretation_id);
    for (int size = 1; size <= nd; size++) {
        int pick[PLCVEC_INTERPRETATION_COUNT];
        for (int q = 0; q < size; q++)
            pick[q] = q;
        do {
            uint8_t trial[PLCVEC_INTERPRETATION_COUNT];
            memcpy(trial, inf->followed, sizeof trial);
            for (int q = 0; q < size; q++)
                trial[differ[pick[q]]] = inf->choice[differ[pick[q]]];
            if (passes_under(r, trial)) {
                for (int q = 0; q < size; q++)
                    out[q] = differ[pick[q]];
                return size;
            }
        } while (next_subset(pick, size, nd));
    }
    memcpy(out, differ, (size_t)nd * sizeof *out);
    return nd;
}
