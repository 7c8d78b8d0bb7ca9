/* Interpretation choices: what an implementation declares, the alternative followed for each
 * interpretation (declared, else the default; CONTRACT.md, "Declaring your interpretation"), and
 * the interpretations that decide a differing field, for a failure block's `judged by:` line. */
#include <stdio.h>
#include <string.h>

#include "choices.h"
#include "expect.h"

int plcvec_choices_resolve(const plcvec_impl *impl, uint8_t *alternative, char *err, size_t errlen)
{
    uint8_t declared[PLCVEC_INTERPRETATION_COUNT] = {0};
    for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
        alternative[i] = plcvec_interpretations[i].default_alternative;
    const char *who = impl->name ? impl->name : "the implementation";
    for (size_t c = 0; c < impl->n_choices; c++) {
        const plcvec_choice *ch = &impl->choices[c];
        if (ch->interpretation >= PLCVEC_INTERPRETATION_COUNT ||
            ch->alternative >= plcvec_interpretations[ch->interpretation].n_alternatives) {
            snprintf(err, errlen, "%s declares interpretation %u alternative %u, which the suite does not have", who,
                     ch->interpretation, ch->alternative);
            return -1;
        }
        const plcvec_interpretation_info *info = &plcvec_interpretations[ch->interpretation];
        if (declared[ch->interpretation] && alternative[ch->interpretation] != ch->alternative) {
            snprintf(err, errlen, "%s declares %s=%s and %s=%s: one interpretation, two alternatives", who, info->id,
                     info->alternatives[alternative[ch->interpretation]], info->id, info->alternatives[ch->alternative]);
            return -1;
        }
        declared[ch->interpretation] = 1;
        alternative[ch->interpretation] = ch->alternative;
    }
    return 0;
}

/* The one interpretation of v in which `entry` differs from `alternative`; -1 when it differs in
 * none, in more than one, or names not every one of v's. */
static int differs_in_one(const plcvec_vector *v, const plcvec_alternative *entry, const uint8_t *alternative)
{
    int differing = -1;
    for (size_t i = 0; i < v->n_interpretations; i++) {
        int interp = v->interpretations[i], a = plcvec_expect_offered(entry, interp);
        if (a < 0 || (a != alternative[interp] && differing >= 0))
            return -1;
        if (a != alternative[interp])
            differing = interp;
    }
    return differing;
}

uint64_t plcvec_choices_deciders(const plcvec_vector *v, const uint8_t *alternative, const plcvec_alternative *followed,
                                 int step, int device)
{
    if (step < 0 || !v->n_interpretations)
        return 0;
    plcvec_cell here = {0, 0, 0};
    int listed = plcvec_expect_value(v, followed, (size_t)step, device, &here);
    uint64_t found = 0;
    for (size_t o = 0; o <= v->n_alternatives; o++) {
        const plcvec_alternative *entry = o == 0 ? NULL : &v->alternatives[o - 1];
        if (entry == followed || (entry && entry->n_expect != v->n_steps))
            continue;
        int differing = differs_in_one(v, entry, alternative);
        if (differing < 0 || (found >> differing & 1))
            continue;
        plcvec_cell there = {0, 0, 0};
        int listed_there = plcvec_expect_value(v, entry, (size_t)step, device, &there);
        if ((device >= 0 && plcvec_expect_unjudged(entry, device)) || listed != listed_there ||
            (listed && (here.type != there.type || here.value != there.value)))
            found |= UINT64_C(1) << differing;
    }
    return found;
}

size_t plcvec_choices_judged_by(uint64_t which, const uint8_t *alternative, plcvec_choice *out)
{
    size_t n = 0;
    for (;;) {
        int next = -1;
        for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
            if ((which >> i & 1) && (next < 0 || strcmp(plcvec_interpretations[i].id, plcvec_interpretations[next].id) < 0))
                next = i;
        if (next < 0)
            return n;
        which &= ~(UINT64_C(1) << next);
        out[n].interpretation = (uint8_t)next;
        out[n++].alternative = alternative[next];
    }
}
