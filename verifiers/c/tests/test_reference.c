/* The reference passes every vector under every combination of alternatives of its family's
 * interpretations (declaring the combination it follows), judged by the library's runner. */
#include <stdio.h>
#include <stdlib.h>

#include "reference.h"

int main(void)
{
    size_t runs = 0, failures = 0, combinations = 0;
    for (int f = 0; f < PLCVEC_FAMILY_COUNT; f++) {
        int interps[PLCVEC_INTERPRETATION_COUNT], n = 0;
        for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
            if (plcvec_interpretations[i].families >> f & 1)
                interps[n++] = i;
        int pick[PLCVEC_INTERPRETATION_COUNT] = {0};
        for (;;) {
            plcvec_reference ref;
            plcvec_reference_init(&ref);
            for (int k = 0; k < n; k++)
                ref.declared[interps[k]] = ref.machine.follows[interps[k]] = (uint8_t)pick[k];
            plcvec_impl impl = plcvec_reference_impl(&ref);
            char err[256];
            plcvec_judge *j = plcvec_judge_new(&impl, err, sizeof err);
            if (!j) {
                fprintf(stderr, "%s\n", err);
                return 2;
            }
            combinations++;
            for (size_t i = 0; i < plcvec_count(); i++) {
                const plcvec_vector *v = plcvec_at(i);
                if ((int)v->family != f)
                    continue;
                const plcvec_verdict *vd = plcvec_judge_vector(j, v);
                runs++;
                if (vd->status != PLCVEC_PASS) {
                    if (failures++ < 10)
                        plcvec_print_verdict(stdout, vd);
                }
            }
            plcvec_judge_free(j);
            int k = 0;      /* the next combination: an odometer over the alternatives */
            while (k < n && ++pick[k] == plcvec_interpretations[interps[k]].n_alternatives)
                pick[k++] = 0;
            if (k == n)
                break;
        }
    }
    printf("reference: %zu vector runs over %zu combinations of alternatives, %zu not passed\n", runs, combinations,
           failures);
    return failures || runs < plcvec_count() ? 1 : 0;
}
