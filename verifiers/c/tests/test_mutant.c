/* A mutant is rejected: judged by the library's runner under its declared alternatives, some
 * vector of each family its bug is in fails. Prints the first vectors that catch it.
 * `test_mutant --list` prints the mutants' names (checked against the tests CMake registers);
 * `test_mutant NAME --run` runs the whole suite through plcvec_run, whose text CI compares with
 * plcvec verify's over the stdio adapter serving the same mutant (so its declarations are written
 * as plcvec verify takes them, --choose ID=ALT; test_rollup checks the C form). */
#include <stdio.h>
#include <string.h>

#include "reference.h"
#include "rollup.h"

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "--list") == 0) {
        for (size_t i = 0; i < plcvec_mutant_count; i++)
            printf("%s\n", plcvec_mutants[i].name);
        return 0;
    }
    int whole_run = argc == 3 && strcmp(argv[2], "--run") == 0;
    const plcvec_mutant *mutant = argc == 2 || whole_run ? plcvec_mutant_named(argv[1]) : NULL;
    if (!mutant) {
        fprintf(stderr, "usage: test_mutant NAME [--run] | --list\n");
        return 2;
    }
    static plcvec_reference ref;
    plcvec_reference_init(&ref);
    mutant->apply(&ref);
    plcvec_impl impl = plcvec_reference_impl(&ref);
    if (whole_run) {
        plcvec_rollup_declaration_form(PLCVEC_DECLARE_CHOOSE);
        return plcvec_run(&impl, NULL, NULL);
    }
    char err[256];
    plcvec_judge *j = plcvec_judge_new(&impl, err, sizeof err);
    if (!j)
        return 2;
    int rejected_everywhere = 1;
    for (int f = 0; f < PLCVEC_FAMILY_COUNT; f++) {
        if (!strstr(mutant->families, plcvec_family_names[f]))
            continue;
        size_t caught = 0, total = 0;
        for (size_t i = 0; i < plcvec_count(); i++) {
            const plcvec_vector *v = plcvec_at(i);
            if ((int)v->family != f)
                continue;
            total++;
            const plcvec_verdict *vd = plcvec_judge_vector(j, v);
            if (vd->status == PLCVEC_FAIL) {
                if (caught++ == 0)
                    plcvec_print_verdict(stdout, vd);
            } else if (vd->status != PLCVEC_PASS) {
                plcvec_print_verdict(stdout, vd);
                rejected_everywhere = 0;
            }
        }
        printf("%s in %s: caught by %zu of %zu vectors\n", mutant->name, plcvec_family_names[f], caught, total);
        if (!caught)
            rejected_everywhere = 0;
    }
    plcvec_judge_free(j);
    return rejected_everywhere ? 0 : 1;
}
