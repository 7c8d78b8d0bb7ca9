/* What the generated tables (src/generated/, rendered by `plcvec export --lang c`) are made of.
 *
 * A vector is one initializer of plcvec_vector; its lists are compound literals, so a vector
 * stays one block of a few lines and a changed vector changes only those lines. The macros keep
 * those lines short: W(D100, 11) is the word D100 = 11, B(SM709, 0) the bit SM709 = false. */
#ifndef PLCVEC_TABLE_H
#define PLCVEC_TABLE_H

#include "plcvec/plcvec.h"

typedef struct plcvec_family_table {
    const plcvec_vector *vectors;
    size_t count;
    const char *const *clauses;
    size_t n_clauses;
} plcvec_family_table;

extern const plcvec_family_table *const plcvec_tables[PLCVEC_FAMILY_COUNT];

/* The ids the generator merged into the vector that is the same test (the manifest's `merged`),
 * sorted by the old id; `into` may itself be merged again. */
typedef struct plcvec_merged_id {
    const char *id;
    const char *into;
} plcvec_merged_id;
extern const plcvec_merged_id plcvec_merged_ids[];
extern const size_t plcvec_n_merged_ids;

/* How a C implementer declares each alternative (TEXT.md, "The declaration in each runner"): the
 * generated enumerators' own names, {PLCVEC_INTERP_X, PLCVEC_X_ALT}. */
typedef struct plcvec_declaration_names {
    const char *interpretation;             /* "PLCVEC_INTERP_FX5_SM709_SCOPE" */
    const char *const *alternatives;        /* "PLCVEC_FX5_SM709_SCOPE_ALL_WORDS", ... */
} plcvec_declaration_names;
extern const plcvec_declaration_names plcvec_declarations[PLCVEC_INTERPRETATION_COUNT];

/* The tables were exported from vector files of schema 1.x; a 2.x file may mean something else by
 * the same fields, so a library written for 1.x refuses to build from it (CONTRACT.md, Versioning). */
#if PLCVEC_SCHEMA_MAJOR != 1
#error "src/generated/ was exported from vector files of another major schema_version; this library reads 1.x"
#endif

_Static_assert(PLCVEC_TAG_COUNT <= 64, "a vector's tags are a 64-bit set");
_Static_assert(PLCVEC_INTERPRETATION_COUNT <= 64, "the interpretations that decide a field are a 64-bit set");

/* A list and its length (the export counts); NONE is the empty list. */
#define L(type, n, ...) (const type[]){__VA_ARGS__}, n
#define NONE NULL, 0
#define W(dev, v) {PLCVEC_DEV_##dev, v, PLCVEC_WORD}
#define B(dev, v) {PLCVEC_DEV_##dev, v, PLCVEC_BIT}
#define T(tag) (UINT64_C(1) << PLCVEC_TAG_##tag)
#define OPD(name, dev) {name, PLCVEC_DEV_##dev, 0, 0}
#define K(name, value) {name, 0, 1, value}
#define CLK(fields, y, mo, d, h, mi, s) &(const plcvec_clock){fields, y, mo, d, h, mi, s}
#define X(devices, result) {devices, result}
#define S(rlo, en, input, elapsed, clock, set, expect) {rlo, en, input, elapsed, clock, set, expect}
#define O(category) PLCVEC_OUTCOME_##category
#define CH(interp, alt) {PLCVEC_INTERP_##interp, PLCVEC_##interp##_##alt}
#define U(interp, devices) {PLCVEC_INTERP_##interp, devices}
#define A(choices, category, expect, unjudged) {choices, category, expect, unjudged}

#endif
