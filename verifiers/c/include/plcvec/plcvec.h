/* plcvec: conformance test vectors for PLC clock and calendar instructions, for C and C++.
 *
 * The golden vectors are compiled into the library (no files, no JSON at run time). An
 * implementation (an emulator, a soft-PLC, a ladder translator) is described by a plcvec_impl, a
 * struct of function pointers at the level of verifiers/CONTRACT.md; the runner gives it each
 * vector's initial state and inputs, and judges what it reports after every step, field by field.
 * Emulators that would rather only "execute this instruction on my memory" fill a plcvec_machine
 * instead and wrap it with plcvec_machine_impl(). */
#ifndef PLCVEC_H
#define PLCVEC_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "plcvec/generated/names.h"

/* A public name kept after a rename until the release CHANGES.md names (its Deprecated entry) says
 * so in a comment above it, and is not marked for the compiler unless asked: the deprecated
 * attribute's warning is on by default in GCC and Clang, so it would fail every program built with
 * -Werror that still uses the old name, and a minor upgrade must not turn a pinned CI red
 * (CONTRACT.md, Compatibility policy). Define PLCVEC_WARN_DEPRECATED before this header (or
 * -DPLCVEC_WARN_DEPRECATED) to have the compiler name each use of an old name, and its new one. */
#if defined(PLCVEC_WARN_DEPRECATED) && defined(__GNUC__)
#define PLCVEC_DEPRECATED(why) __attribute__((deprecated(why)))
#else
#define PLCVEC_DEPRECATED(why)
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- the vectors ------------------------------------------------------------------------- */

/* What a device holds. A word is the raw 16 bits (0..65535); a bit is 0 or 1, and is a
 * different thing from a word holding 1: the runner compares the type too. */
typedef enum plcvec_type { PLCVEC_WORD = 0, PLCVEC_BIT = 1 } plcvec_type;

/* One device and its value. `device` is a plcvec_device_id (plcvec_devices[device].name). */
typedef struct plcvec_cell {
    uint16_t device;
    uint16_t value;
    uint8_t type;               /* plcvec_type */
} plcvec_cell;

/* An operand: a device ("D100"; a multi-word operand occupies D100, D101, ...) or a K/H constant. */
typedef struct plcvec_operand {
    const char *name;           /* the manual's name: "s1", "d", "S1", "C", ... */
    uint16_t device;            /* plcvec_device_id, when !is_constant */
    uint8_t is_constant;
    int32_t constant;
} plcvec_operand;

/* assumes.device_sizes: the number of points of a device type ({"D", 8000}: D0 to D7999). */
typedef struct plcvec_size {
    const char *kind;
    uint32_t points;
} plcvec_size;

/* The injected current clock of a step; `fields` says which are given (PLCVEC_CLOCK_*). */
enum {
    PLCVEC_CLOCK_YEAR = 1, PLCVEC_CLOCK_MONTH = 2, PLCVEC_CLOCK_DAY = 4,
    PLCVEC_CLOCK_HOUR = 8, PLCVEC_CLOCK_MINUTE = 16, PLCVEC_CLOCK_SECOND = 32
};
typedef struct plcvec_clock {
    uint8_t fields;
    int32_t year, month, day, hour, minute, second;
} plcvec_clock;

/* No contact result: the instruction is not a contact (TADD, HOUR), or an input is absent. */
#define PLCVEC_NONE (-1)

/* What one step expects: the devices whose value changes in it, and the contact result. */
typedef struct plcvec_expect {
    const plcvec_cell *devices;
    uint16_t n_devices;
    int8_t result;              /* 0, 1, or PLCVEC_NONE */
} plcvec_expect;

/* One execution of the instruction (one scan): the outside world's writes, then the inputs. */
typedef struct plcvec_step {
    int8_t rlo_in;              /* the logic state before an AND/OR form: 0, 1 or PLCVEC_NONE */
    int8_t en;                  /* TADD/TADDP's execution condition: 0, 1 or PLCVEC_NONE */
    int8_t input;               /* HOUR's input this scan: 0, 1 or PLCVEC_NONE */
    int64_t elapsed_ms;         /* HOUR: ms since the previous execution, or PLCVEC_NONE */
    const plcvec_clock *clock;  /* the current clock, or NULL */
    const plcvec_cell *set;     /* written before the execution (the program, an HMI) */
    uint16_t n_set;
    plcvec_expect expect;       /* under the default alternatives; see plcvec_expected() */
} plcvec_step;

typedef enum plcvec_category {
    PLCVEC_OUTCOME_VALUE, PLCVEC_OUTCOME_ERROR, PLCVEC_OUTCOME_IMPLEMENTATION_DEFINED
} plcvec_category;

/* A declared alternative: interpretation (plcvec_interpretation) and its alternative's number. */
typedef struct plcvec_choice {
    uint8_t interpretation;
    uint8_t alternative;
} plcvec_choice;

/* Devices an alternative leaves unjudged: where the pages define no behaviour for a state, the
 * alternative that reads them so does not compare these devices (they are in the vector's
 * initial.devices, so writing them is no stray write). */
typedef struct plcvec_unjudged {
    uint8_t interpretation;     /* one of the entry's choices (plcvec_interpretation) */
    const uint16_t *devices;    /* plcvec_device_ids, sorted by name */
    uint16_t n_devices;
} plcvec_unjudged;

/* The expectation of a vector under one combination of alternatives other than the defaults. */
typedef struct plcvec_alternative {
    const plcvec_choice *choices;
    uint16_t n_choices;
    uint8_t category;           /* plcvec_category */
    const plcvec_expect *expect;    /* one per step */
    uint16_t n_expect;
    const plcvec_unjudged *unjudged;    /* sorted by interpretation id; none: every device is judged */
    uint16_t n_unjudged;
} plcvec_alternative;

typedef struct plcvec_vector {
    const char *id;             /* stable: safe in skip lists and test filters */
    const char *description;
    plcvec_instruction instruction;
    plcvec_family family;
    uint64_t tags;              /* bit (1 << plcvec_tag) */
    const uint8_t *clauses;     /* indexes into the family's clauses: see plcvec_clause() */
    uint16_t n_clauses;
    const plcvec_size *sizes;
    uint16_t n_sizes;
    const plcvec_cell *devices; /* initial.devices: every device read or possibly written */
    uint16_t n_devices;
    const uint16_t *scratch;    /* work-area words: the implementation's own, never compared */
    uint16_t n_scratch;
    const plcvec_operand *operands;
    uint16_t n_operands;
    const plcvec_step *steps;
    uint16_t n_steps;
    uint8_t category;           /* plcvec_category under the default alternatives */
    const uint8_t *interpretations; /* the interpretations the outcome depends on */
    uint16_t n_interpretations;
    const plcvec_alternative *alternatives;
    uint16_t n_alternatives;
} plcvec_vector;

/* Names of the generated enums (indexed by the enum). */
extern const char *const plcvec_family_names[PLCVEC_FAMILY_COUNT];
extern const char *const plcvec_instruction_names[PLCVEC_INSTRUCTION_COUNT];
extern const plcvec_family plcvec_instruction_family[PLCVEC_INSTRUCTION_COUNT];
extern const char *const plcvec_tag_names[PLCVEC_TAG_COUNT];

/* What each instruction is, as values: no need to parse "LDTM<=" or "AND <=DT". */
typedef struct plcvec_instruction_info {
    const char *name;           /* "LDTM<=", "AND <=DT", "TADDP" */
    const char *st;             /* the structured-text spelling ("LDTM_LE"), "" where the page gives none */
    plcvec_family family;
    plcvec_form form;           /* LD / AND / OR; PLCVEC_FORM_NONE for TADD, TADDP, HOUR */
    plcvec_condition condition; /* = <> < <= > >=; PLCVEC_CONDITION_NONE for what compares nothing */
    plcvec_execution execution; /* every scan, or on the rising edge of its condition (TADDP) */
} plcvec_instruction_info;
extern const plcvec_instruction_info plcvec_instructions[PLCVEC_INSTRUCTION_COUNT];
extern const char *const plcvec_form_names[PLCVEC_FORM_COUNT];           /* "" for NONE, "LD", ... */
extern const char *const plcvec_condition_names[PLCVEC_CONDITION_COUNT]; /* "" for NONE, "=", "<>", ... */
extern const char *const plcvec_execution_names[PLCVEC_EXECUTION_COUNT]; /* "every-scan", "rising-edge" */

typedef struct plcvec_interpretation_info {
    const char *id;             /* "FX5-SM709-SCOPE" */
    const char *question;
    const char *const *alternatives;    /* their ids, numbered as the generated enums */
    uint8_t n_alternatives;
    uint8_t default_alternative;
    uint32_t families;          /* bit (1 << plcvec_family) for each family it belongs to */
} plcvec_interpretation_info;
extern const plcvec_interpretation_info plcvec_interpretations[PLCVEC_INTERPRETATION_COUNT];

typedef struct plcvec_device_info {
    const char *name;           /* "D100", "SM709", "P_EQ" */
    const char *kind;           /* "D", "SM", "P_EQ" */
    int32_t number;             /* 100, 709, -1 for a device without a number */
} plcvec_device_info;
extern const plcvec_device_info plcvec_devices[PLCVEC_DEVICE_COUNT];

/* A device by id: one of plcvec_devices[], or one added by plcvec_device_intern(); NULL if none. */
const plcvec_device_info *plcvec_device(int id);
/* The id of a device by name, adding it when the suite does not name it ("D5000"): for runners
 * that build vectors at run time (the stdio adapter). -1 for a name longer than 23 characters
 * or out of memory. Not thread-safe. */
int plcvec_device_intern(const char *name);

size_t plcvec_count(void);                              /* every vector of the suite */
const plcvec_vector *plcvec_at(size_t index);           /* in family order, then by id */
const plcvec_vector *plcvec_find(const char *id);       /* NULL if the suite has no such vector */
/* The id a vector id that the suite merged into another became (the vector files' `merged` map,
 * followed to its end), or NULL when the id was never merged. */
const char *plcvec_merged_into(const char *id);
const char *plcvec_clause(const plcvec_vector *v, size_t i);    /* "fx5-time-add#carry" */
const char *plcvec_operand_device_name(const plcvec_operand *op);
const plcvec_operand *plcvec_operand_named(const plcvec_vector *v, const char *name);
int plcvec_device_named(const char *name);              /* its id (interned ones too), or -1 */
long plcvec_size_of(const plcvec_vector *v, const char *kind);  /* points, or -1 if not stated */
/* "FX5-SM709-SCOPE" -> its plcvec_interpretation, and an alternative's number; -1 if unknown. */
int plcvec_interpretation_named(const char *id);
int plcvec_alternative_named(int interpretation, const char *alternative);

/* A test name for frameworks that allow only letters, digits and '_' (GoogleTest): the id with
 * "/" as "__", "<" ">" "=" "+" as LT GT EQ PLUS, "-" " " "." as "_", anything else as _xHH.
 * fx5-time-add/TADD/carry/below-wrap -> fx5_time_add__TADD__carry__below_wrap. Returns the
 * length it needed (truncated to size). */
size_t plcvec_test_name(const plcvec_vector *v, char *buf, size_t size);

/* ---- selection ---------------------------------------------------------------------------- */

/* Filters: OR within one list, AND between lists; an empty list does not filter. The lists hold
 * spec names ("fx5-time-add", "TADDP", "boundary", "FX5-SM709-SCOPE"); `ids` holds glob patterns
 * (*, ?, [abc], [!abc]) matched against the whole id. shard_k/shard_n (1 <= k <= n, or 0/0)
 * keep the vectors with crc32(id) % n + 1 == k, the rule of every plcvec runner, so shards agree
 * across languages and adding a vector moves no other. */
typedef struct plcvec_selection {
    const char *const *families; size_t n_families;
    const char *const *instructions; size_t n_instructions;
    const char *const *tags; size_t n_tags;
    const char *const *ids; size_t n_ids;
    const char *const *interpretations; size_t n_interpretations;
    unsigned shard_k, shard_n;
} plcvec_selection;

/* The selected vectors, in suite order, into a malloc'd array (free it with free()). Returns
 * the number selected, or -1 with a message in err (an unknown name, a bad shard). Selecting
 * nothing is not an error here; plcvec_run() treats it as one. */
long plcvec_select(const plcvec_selection *sel, const plcvec_vector ***out, char *err, size_t errlen);
int plcvec_selected(const plcvec_selection *sel, const plcvec_vector *v);  /* after validation */
/* The vectors of `family` (NULL: every family) that the variables PLCVEC_FAMILY, PLCVEC_INSTRUCTION,
 * PLCVEC_TAG, PLCVEC_ID, PLCVEC_INTERPRETATION (comma-separated) and PLCVEC_SHARD select, as
 * plcvec_main reads them, for a test runner of your own (plcvec/gtest.hpp). -1 and err on a
 * mistake in any PLCVEC_* variable. */
long plcvec_select_from_environment(const char *family, const plcvec_vector ***out, char *err, size_t errlen);
uint32_t plcvec_crc32(const char *text);                /* zlib's CRC-32 of the bytes */
int plcvec_glob(const char *pattern, const char *text); /* fnmatchcase: 1 if it matches */

/* ---- the implementation --------------------------------------------------------------------- */

/* Where an implementation reports what it did with one vector (owned by the runner). */
typedef struct plcvec_out plcvec_out;

/* After executing step `step` (0, 1, ...): the contact result (0/1, or PLCVEC_NONE for TADD and
 * HOUR), then every device of the vector (v->devices; scratch may be left out) and any other
 * device the step wrote, each once. Devices are plcvec_device_ids; one outside the table of
 * names is reported by name with plcvec_out_named(). */
void plcvec_out_step(plcvec_out *out, int result);
void plcvec_out_device(plcvec_out *out, int device, plcvec_type type, unsigned value);
void plcvec_out_named(plcvec_out *out, const char *device, plcvec_type type, unsigned value);
/* Instead of steps: cannot run this vector (a reason: "no R devices"), or failed on it. Both
 * return the value run() returns. */
int plcvec_out_skip(plcvec_out *out, const char *reason);
int plcvec_out_error(plcvec_out *out, const char *message);

/* Reading back what was reported, for runners of your own (the stdio adapter is one). */
typedef struct plcvec_reported {
    int device;                 /* plcvec_device_id, or -1: see name */
    uint8_t type;               /* plcvec_type */
    uint32_t value;
    char name[24];              /* set when device is -1 */
} plcvec_reported;
plcvec_out *plcvec_out_new(void);
void plcvec_out_free(plcvec_out *out);
void plcvec_out_reset(plcvec_out *out);
/* 0: ran (read the steps), 1: skipped, 2: error; *message says why. */
int plcvec_out_status(const plcvec_out *out, const char **message);
size_t plcvec_out_step_count(const plcvec_out *out);
int plcvec_out_result(const plcvec_out *out, size_t step);  /* 0, 1 or PLCVEC_NONE */
const plcvec_reported *plcvec_out_cells(const plcvec_out *out, size_t step, size_t *n);

/* An implementation, at the level of the contract. */
typedef struct plcvec_impl {
    const char *name;
    void *ctx;                  /* passed back to every function */
    /* The alternative it follows for some interpretations; the others take their default. */
    const plcvec_choice *choices;
    size_t n_choices;
    /* 1 if it implements the instruction; NULL: every instruction. Others are skipped. */
    int (*supports)(void *ctx, plcvec_instruction instruction);
    /* Run one vector from its own initial state (nothing carries over from another vector):
     * for each step apply `set`, execute with the step's inputs, then report with plcvec_out_*.
     * Return 0, or what plcvec_out_skip()/plcvec_out_error() return. */
    int (*run)(void *ctx, const plcvec_vector *v, plcvec_out *out);
    /* Devices the CPU writes on its own account (diagnostic relays and registers: "SM0", "SD0"),
     * NULL-terminated; NULL: none. A write to one outside the vector is not a stray write; one the
     * vector lists is compared as usual. */
    const char *const *cpu_writes;
} plcvec_impl;

/* The thin helper: "execute this instruction on my memory". The runner writes the vector's
 * devices into your memory, runs each step, and reads the devices back. */
typedef struct plcvec_machine {
    const char *name;
    void *ctx;
    const plcvec_choice *choices;
    size_t n_choices;
    int (*supports)(void *ctx, plcvec_instruction instruction);    /* NULL: every one */
    /* Power on: forget every device value and all internal state (TADDP's edge, HOUR's work
     * area); the vector's device sizes are given. Return nonzero to skip the vector. */
    int (*reset)(void *ctx, const plcvec_vector *v);
    void (*write)(void *ctx, const char *device, plcvec_type type, unsigned value);
    unsigned (*read)(void *ctx, const char *device);
    /* One scan: execute v->instruction with v->operands and the step's inputs; return the
     * contact result (0/1) or PLCVEC_NONE. Return -2 to report an error instead. */
    int (*execute)(void *ctx, const plcvec_vector *v, const plcvec_step *step);
    /* Optional: call `seen` for each device written since reset() (so writes outside the vector
     * are caught). NULL: only the vector's own devices are read back. */
    void (*written)(void *ctx, void (*seen)(void *arg, const char *device, plcvec_type type, unsigned value), void *arg);
    const char *const *cpu_writes;  /* as plcvec_impl.cpu_writes */
} plcvec_machine;

/* An impl running `m` (which must outlive it). */
plcvec_impl plcvec_machine_impl(const plcvec_machine *m);

/* ---- judging -------------------------------------------------------------------------------- */

typedef enum plcvec_status {
    PLCVEC_PASS, PLCVEC_FAIL, PLCVEC_ERROR, PLCVEC_SKIP, PLCVEC_XFAIL, PLCVEC_STALE
} plcvec_status;
extern const char *const plcvec_status_names[];

/* One field that differs. `device` is a plcvec_device_id, or -1 for the contact result, or -2
 * for the number of steps; `name` is set for a device outside the table. has_* are 0 when the
 * value is absent (not reported, or not in the vector). */
typedef struct plcvec_problem {
    int step;
    int device;
    char name[24];
    uint8_t has_expected, expected_type, has_actual, actual_type, has_before, before_type;
    uint32_t expected, actual, before;
    uint8_t twice, second_type; /* reported twice with two values: actual, then second */
    uint32_t second;
    /* What the implementation held before the step (its own report of the step before, with this
     * step's `set` over it; the vector's for step 0), and whether the step must keep the device. */
    uint8_t has_held, held_type, keep;
    uint32_t held;
    uint64_t deciders;          /* bit (1 << plcvec_interpretation) of those that decide this field */
} plcvec_problem;

/* A known failure: listed vectors that fail are XFAIL; listed vectors that pass are STALE (a
 * failure), and so is an id the suite does not have. Ids are exact, never patterns. Messages name
 * the entry as FILE:LINE; a list written in code may give its own (__FILE__, __LINE__), and an entry
 * without a file is named "(in code)". */
typedef struct plcvec_known_failure {
    const char *id;
    const char *reason;
    const char *file;           /* the known-failures file that lists it; NULL: a list in code */
    int line;                   /* the line of its [[known-failure]] header; 0: none */
} plcvec_known_failure;

/* Read a known-failures TOML file (CONTRACT.md: [[known-failure]] entries of `id` and `reason`):
 * 0 and a malloc'd list (free it with plcvec_known_free), or -1 with "FILE:LINE: why" in err. A
 * path that is not a regular file (a named pipe, a device, a folder, a loop of symbolic links) is
 * refused by name before it is opened. */
int plcvec_known_load(const char *path, plcvec_known_failure **list, size_t *n, char *err, size_t errlen);
void plcvec_known_free(plcvec_known_failure *list, size_t n);
/* Write ids (sorted in place) as a known-failures file, each with `reason`, replacing the file
 * whole or not at all (a path that is there and is not a regular file is refused); 0, or -1 and err. */
int plcvec_known_write(const char *path, const char **ids, size_t n, const char *reason, char *err, size_t errlen);

/* The verdict on one vector. */
typedef struct plcvec_verdict {
    const plcvec_vector *vector;
    plcvec_status status;
    char message[512];          /* skip/error/xfail/stale reason */
    const plcvec_problem *problems;
    size_t n_problems;
    plcvec_choice choices[PLCVEC_INTERPRETATION_COUNT];   /* judged by: the interpretations that decide a differing field */
    size_t n_choices;
    const plcvec_alternative *applied;  /* the expectations judged against; NULL: the vector's own */
    /* A failing answer: bit o when it passes under offered expectation o (0: the vector's own, o:
     * alternatives[o - 1]); what the roll-up by reading is built on. */
    uint64_t offered_passes;
} plcvec_verdict;

/* A judge: an implementation and its resolved alternatives, with the buffers a run needs. */
typedef struct plcvec_judge plcvec_judge;

/* NULL with a message in err when the implementation declares an unknown interpretation or
 * alternative. Not thread-safe: use one judge per thread. */
plcvec_judge *plcvec_judge_new(const plcvec_impl *impl, char *err, size_t errlen);
void plcvec_judge_free(plcvec_judge *j);
/* The alternative the judge follows for an interpretation (declared, or the default). */
int plcvec_judge_alternative(const plcvec_judge *j, int interpretation);
/* Run one vector and judge it. The verdict's problems live until the next call. */
const plcvec_verdict *plcvec_judge_vector(plcvec_judge *j, const plcvec_vector *v);
/* Apply a known-failure list to a verdict (PASS -> STALE, FAIL/ERROR -> XFAIL). */
void plcvec_known_apply(plcvec_verdict *verdict, const plcvec_known_failure *known, size_t n_known);
/* Deprecated since 0.3.0, removed in 0.4.0: the old name of plcvec_known_apply, the same function. */
PLCVEC_DEPRECATED("use plcvec_known_apply, the same function; plcvec_apply_known is removed in plcvec 0.4.0")
void plcvec_apply_known(plcvec_verdict *verdict, const plcvec_known_failure *known, size_t n_known);
/* The expectation of v for step i under the judge's alternatives. */
const plcvec_expect *plcvec_expected(const plcvec_judge *j, const plcvec_vector *v, size_t step);

/* The verdict as people read it (verifiers/parity/TEXT.md, "The failure block"): status and id,
 * description, the alternatives it was judged by, the devices the alternative followed leaves
 * unjudged, one line per field (step, device, expected, actual), the message, the spec clauses. */
void plcvec_print_verdict(FILE *f, const plcvec_verdict *verdict);
/* The same into a buffer (truncated to size); returns the length it needed. */
size_t plcvec_format_verdict(char *buf, size_t size, const plcvec_verdict *verdict);

/* ---- running a selection ---------------------------------------------------------------------- */

typedef struct plcvec_options {
    plcvec_selection selection;
    const plcvec_known_failure *known;
    size_t n_known;
    FILE *log;                  /* where failures and the summary go; NULL: stdout */
    int verbose;                /* also print skipped and xfail verdicts */
    const char *write_expectations; /* write the run's failures here as a known-failures file */
} plcvec_options;

/* plcvec_run's and plcvec_main's exit statuses, those of `plcvec verify` (CONTRACT.md). */
enum {
    PLCVEC_EXIT_PASSED = 0,     /* every selected vector passed or is a known failure; one passed */
    PLCVEC_EXIT_FAILED = 1,     /* a failure, an error, a stale known failure, a run ended early */
    PLCVEC_EXIT_USAGE = 2,      /* an unknown name, a bad variable or file, a bad declaration */
    PLCVEC_EXIT_NOTHING_TESTED = 5  /* no vector selected, or none passed (all skipped or known failures) */
};

typedef struct plcvec_summary {
    size_t selected, passed, failed, errors, skipped, xfail, stale;
    size_t stale_unknown;       /* of the stale: known failures naming no vector of the suite */
} plcvec_summary;

/* Judge every selected vector, print each failure as a field-level diff, then the end of the run
 * (plcvec_report_end: the roll-up by reading, the skips by reason, the summary), in the words of
 * verifiers/parity/TEXT.md. Returns a PLCVEC_EXIT_*: 1 on any failure, error or stale entry; 5 when
 * nothing was selected or nothing passed (every vector skipped or a known failure); 2 on a usage
 * error (an unknown name, an id glob matching no id, a bad shard, an unknown declared alternative,
 * a bad PLCVEC_TIMEOUT, a known-failures file that cannot be written). */
int plcvec_run(const plcvec_impl *impl, const plcvec_options *opt, plcvec_summary *summary);

/* A run's record, for a test runner of your own (plcvec/gtest.hpp is one): add each vector's
 * verdict as it is judged, then print the end of the run as plcvec_run does. */
typedef struct plcvec_report plcvec_report;
/* A record of verdicts judged by j (its alternatives and declarations go into the summary); NULL
 * when out of memory. */
plcvec_report *plcvec_report_new(const plcvec_judge *j);
void plcvec_report_free(plcvec_report *r);
/* One vector's verdict, with the known failures applied (plcvec_known_apply); 0, or -1 when out
 * of memory. */
int plcvec_report_add(plcvec_report *r, const plcvec_verdict *verdict);
/* The end of the run, in the words of verifiers/parity/TEXT.md: a STALE block for each of `known`
 * that names no vector of the suite, the roll-up by reading (the failures and known failures that
 * another alternative explains, the declaration that does it, the failures no reading explains),
 * the skips by reason, why a run without failures did not pass, and the summary lines. Returns the
 * run's PLCVEC_EXIT_* status. */
int plcvec_report_end(plcvec_report *r, FILE *log, const plcvec_known_failure *known, size_t n_known, double seconds);

/* The value of a PLCVEC_* setting ("PLCVEC_KNOWN_FAILURES"), read under its old name too
 * ("PLCVEC_EXPECTATIONS") for as long as CONTRACT.md says; NULL when unset. The first call in a
 * process prints, on stderr, one warning for each old name and each PLCVEC_* variable that is no
 * setting (with the nearest setting), as every plcvec runner does. */
const char *plcvec_setting(const char *name);

/* A test program's main(): the options of `plcvec verify` (--family, --instruction, --tag,
 * --id GLOB, --interpretation, each repeatable; --shard K/N, --choose ID=ALT, --expectations FILE,
 * --write-expectations FILE, --list, --verbose), each defaulting to its environment variable
 * (PLCVEC_FAMILY ... PLCVEC_SHARD, PLCVEC_KNOWN_FAILURES (or its old name PLCVEC_EXPECTATIONS),
 * PLCVEC_WRITE_EXPECTATIONS; lists comma-separated; PLCVEC_TIMEOUT bounds each vector), then
 * plcvec_run(). `known` (may be NULL) is added to the file's entries. */
int plcvec_main(const plcvec_impl *impl, const plcvec_known_failure *known, size_t n_known,
                int argc, char **argv);

#ifdef __cplusplus
}
#endif
#endif
