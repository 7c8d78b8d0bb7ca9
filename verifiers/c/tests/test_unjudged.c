/* Devices an alternative leaves unjudged (schema 1.1, the `unjudged` map of an alternatives entry),
 * on hand-made vectors until the golden set has such an entry: under that alternative the devices
 * are not compared and writing them is no stray write; the failure block says which; judged by
 * and the inference weigh them as the rule says. Every expected text is worked out by hand from
 * TEXT.md and the rule, not taken from a run. */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "expect.h"
#include "plcvec/plcvec.h"

#define W(dev, v) {PLCVEC_DEV_##dev, v, PLCVEC_WORD}
#define B(dev, v) {PLCVEC_DEV_##dev, v, PLCVEC_BIT}

/* HOUR D200, M10, D100 (work area D300) with D1 = 0:61:00, a minute out of range; one scan of 1 s
 * with the input on. The defaults (HOUR-D1-OUT-OF-RANGE=as-seconds): 3660 s + 1 s is written back
 * as 1:01:01 and the preset 0:00:05 is reached (M10 on). The alternative `error`: M8004 on, and,
 * in this hand-made vector, D1 left unjudged. */
static const plcvec_cell devices[] = {W(D100, 0), W(D101, 0), W(D102, 5), W(D200, 0), W(D201, 61), W(D202, 0),
                                      W(D300, 0), W(D301, 0), B(M10, 0), B(M8004, 0)};
static const uint16_t scratch[] = {PLCVEC_DEV_D300, PLCVEC_DEV_D301};
static const plcvec_operand operands[] = {{"D1", PLCVEC_DEV_D200, 0, 0}, {"D2", PLCVEC_DEV_M10, 0, 0},
                                          {"S1", PLCVEC_DEV_D100, 0, 0}, {"D3", PLCVEC_DEV_D300, 0, 0}};
static const plcvec_cell as_seconds[] = {W(D200, 1), W(D201, 1), W(D202, 1), B(M10, 1)};
static const plcvec_cell error_flag[] = {B(M8004, 1)};
static const plcvec_step steps[] = {{PLCVEC_NONE, PLCVEC_NONE, 1, 1000, NULL, NULL, 0, {as_seconds, 4, PLCVEC_NONE}}};
static const uint8_t touched[] = {PLCVEC_INTERP_HOUR_D1_OUT_OF_RANGE};
static const plcvec_choice error_choice[] = {{PLCVEC_INTERP_HOUR_D1_OUT_OF_RANGE, PLCVEC_HOUR_D1_OUT_OF_RANGE_ERROR}};
static const plcvec_expect error_expect[] = {{error_flag, 1, PLCVEC_NONE}};
static const uint16_t d1[] = {PLCVEC_DEV_D200, PLCVEC_DEV_D201, PLCVEC_DEV_D202};
static const plcvec_unjudged leaves_d1[] = {{PLCVEC_INTERP_HOUR_D1_OUT_OF_RANGE, d1, 3}};
static const plcvec_alternative alternatives[] = {{error_choice, 1, PLCVEC_OUTCOME_ERROR, error_expect, 1, leaves_d1, 1}};

static const plcvec_vector vector = {
    "fc6a-hour-meter/HOUR/hand-made/d1-unjudged", "D1 out of range, left unjudged under error.", PLCVEC_INSTR_HOUR,
    PLCVEC_FAMILY_FC6A_HOUR_METER, 0, NULL, 0, NULL, 0, devices, 10, scratch, 2, operands, 4, steps, 1,
    PLCVEC_OUTCOME_IMPLEMENTATION_DEFINED, touched, 1, alternatives, 1};

/* The same with both readings turning M8004 on: they differ only in what they judge of D1. */
static const plcvec_cell both_flag[] = {B(M8004, 1)};
static const plcvec_step flag_steps[] = {{PLCVEC_NONE, PLCVEC_NONE, 1, 1000, NULL, NULL, 0, {both_flag, 1, PLCVEC_NONE}}};
static const plcvec_vector alike = {
    "fc6a-hour-meter/HOUR/hand-made/alike-but-d1", "", PLCVEC_INSTR_HOUR, PLCVEC_FAMILY_FC6A_HOUR_METER, 0, NULL, 0,
    NULL, 0, devices, 10, scratch, 2, operands, 4, flag_steps, 1, PLCVEC_OUTCOME_IMPLEMENTATION_DEFINED, touched, 1,
    alternatives, 1};

/* An answer: D1 as `d1_value` (three words), M10 off, M8004 as `flag`, the preset unchanged. */
typedef struct answer {
    unsigned d1_value;
    int flag;
} answer;

static int run(void *ctx, const plcvec_vector *v, plcvec_out *out)
{
    const answer *a = ctx;
    (void)v;
    plcvec_out_step(out, PLCVEC_NONE);
    const int words[] = {PLCVEC_DEV_D100, PLCVEC_DEV_D101, PLCVEC_DEV_D102};
    const unsigned preset[] = {0, 0, 5};
    for (int i = 0; i < 3; i++) {
        plcvec_out_device(out, words[i], PLCVEC_WORD, preset[i]);
        plcvec_out_device(out, d1[i], PLCVEC_WORD, a->d1_value);
    }
    plcvec_out_device(out, PLCVEC_DEV_M10, PLCVEC_BIT, 0);
    plcvec_out_device(out, PLCVEC_DEV_M8004, PLCVEC_BIT, (unsigned)a->flag);
    return 0;
}

static plcvec_judge *judge(answer *a, int declare_error)
{
    static plcvec_impl impl;
    impl = (plcvec_impl){0};
    impl.name = "hand-made";
    impl.ctx = a;
    impl.run = run;
    impl.choices = declare_error ? error_choice : NULL;
    impl.n_choices = declare_error ? 1 : 0;
    char err[256];
    plcvec_judge *j = plcvec_judge_new(&impl, err, sizeof err);
    CHECK(j != NULL);
    return j;
}

static void block_of(plcvec_judge *j, const plcvec_vector *v, plcvec_status want, const char *text, size_t size)
{
    const plcvec_verdict *vd = plcvec_judge_vector(j, v);
    CHECK(vd->status == want);
    plcvec_format_verdict((char *)text, size, vd);
}

/* Under `error`, D1 is not compared: a D1 written anyhow passes, and it is no stray write. */
static void test_unjudged_devices_are_not_compared(void)
{
    answer a = {7, 1};
    plcvec_judge *j = judge(&a, 1);
    char text[4096];
    block_of(j, &vector, PLCVEC_PASS, text, sizeof text);
    a.flag = 0;     /* M8004 still judged: a failure, whose block names what is left unjudged */
    block_of(j, &vector, PLCVEC_FAIL, text, sizeof text);
    CHECK(strcmp(text, "FAIL fc6a-hour-meter/HOUR/hand-made/d1-unjudged\n"
                       "    HOUR: D1 out of range, left unjudged under error.\n"
                       "    judged by: HOUR-D1-OUT-OF-RANGE=error\n"
                       "    not judged under HOUR-D1-OUT-OF-RANGE=error: D200, D201, D202\n"
                       "    step 0 inputs: input=true, elapsed_ms=1000\n"
                       "    step 0 operands: D1 D200=0 61 0, D2 M10=false, D3 D300 (scratch), S1 D100=0 0 5\n"
                       "    step 0 M8004: expected true, got false (before the step: false)\n") == 0);
    if (!strstr(text, "not judged under"))
        fprintf(stderr, "%s", text);
    plcvec_judge_free(j);
}

/* Under the defaults the same answer fails on D1 (which the vector judges there), and the roll-up
 * finds it passes under HOUR-D1-OUT-OF-RANGE=error, where D1 is left unjudged. */
static void test_inference_passes_over_unjudged(void)
{
    answer a = {7, 1};
    plcvec_judge *j = judge(&a, 0);
    plcvec_report *report = plcvec_report_new(j);
    const plcvec_verdict *vd = plcvec_judge_vector(j, &vector);
    CHECK(vd->status == PLCVEC_FAIL && vd->n_choices == 1);
    CHECK(vd->offered_passes == (UINT64_C(1) << 1));    /* passes under alternatives[0], not its own */
    char text[4096];
    plcvec_format_verdict(text, sizeof text, vd);
    CHECK_HAS(text, "    judged by: HOUR-D1-OUT-OF-RANGE=as-seconds\n    step 0 inputs:");
    CHECK(!strstr(text, "not judged under"));       /* the defaults judge every device */
    CHECK_HAS(text, "    step 0 D200: expected 1, got 7 (before the step: 0)\n");
    CHECK(plcvec_report_add(report, vd) == 0);
    FILE *log = tmpfile();
    CHECK(plcvec_report_end(report, log, NULL, 0, 0.0) == PLCVEC_EXIT_FAILED);
    rewind(log);
    size_t n = fread(text, 1, sizeof text - 1, log);
    text[n] = '\0';
    fclose(log);
    CHECK_HAS(text, "READINGS: 1 of 1 failing vectors pass under other alternatives:\n"
                    "         1  HOUR-D1-OUT-OF-RANGE=error\n"
                    "    declare: {PLCVEC_INTERP_HOUR_D1_OUT_OF_RANGE, PLCVEC_HOUR_D1_OUT_OF_RANGE_ERROR}\n");
    plcvec_report_free(report);
    plcvec_judge_free(j);
}

/* judged by: an interpretation decides a field that the other alternative leaves unjudged, even
 * where both expect the same of the rest. */
static void test_judged_by_counts_unjudged(void)
{
    answer a = {9, 1};
    plcvec_judge *j = judge(&a, 0);
    char text[4096];
    block_of(j, &alike, PLCVEC_FAIL, text, sizeof text);
    CHECK_HAS(text, "    judged by: HOUR-D1-OUT-OF-RANGE=as-seconds\n");
    CHECK_HAS(text, "    step 0 D200: expected 0, got 9 (the step must leave it unchanged)\n");
    plcvec_judge_free(j);
}

/* A vector that passed under the followed combination passes under another when every device that
 * one judges is judged alike under the followed one; a device judged there but unjudged under the
 * followed one makes them differ. */
static void test_passing_vector_under_another_combination(void)
{
    const plcvec_alternative *error = &alike.alternatives[0];
    CHECK(plcvec_expect_same(&alike, error, NULL) == 1);    /* followed: the defaults; under error D1 is unjudged */
    CHECK(plcvec_expect_same(&alike, NULL, error) == 0);    /* followed: error, which never judged D1 */
    CHECK(plcvec_expect_same(&vector, error, NULL) == 0);   /* M8004 differs */
    CHECK(plcvec_expect_unjudged(error, PLCVEC_DEV_D201) && !plcvec_expect_unjudged(error, PLCVEC_DEV_M8004) &&
          !plcvec_expect_unjudged(NULL, PLCVEC_DEV_D201));
}

int main(void)
{
    test_unjudged_devices_are_not_compared();
    test_inference_passes_over_unjudged();
    test_judged_by_counts_unjudged();
    test_passing_vector_under_another_combination();
    printf("test_unjudged: %d failures\n", failures);
    return failures ? 1 : 0;
}
