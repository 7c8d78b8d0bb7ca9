/* The hostile implementations of the shared table of faults (verifiers/parity/faults.toml), run
 * through the README's entry point, plcvec_main. Each is the C reference with one misbehaviour,
 * chosen by PLCVEC_HOSTILE, on the vector PLCVEC_HOSTILE_ON (the reference on every other one):
 * the runner must give `plcvec verify`'s verdict on each. verifiers/c/faults-entry runs it.
 * `not-a-number` has no C hostile: a word is an unsigned integer, which cannot hold a NaN. */
#define _POSIX_C_SOURCE 200809L /* fork, close */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "reference.h"

typedef struct hostile {
    const char *kind;
    const char *on;
    plcvec_impl reference;
    plcvec_out *scratch;
} hostile;

static int is(const hostile *h, const char *kind)
{
    return strcmp(h->kind, kind) == 0;
}

static int listed_unscratched(const plcvec_vector *v, int device)
{
    for (size_t i = 0; i < v->n_scratch; i++)
        if (v->scratch[i] == device)
            return 0;
    for (size_t i = 0; i < v->n_devices; i++)
        if (v->devices[i].device == device)
            return 1;
    return 0;
}

/* The reference's answer, passed on with one change (or none). */
static int forward(hostile *h, const plcvec_vector *v, plcvec_out *out, int target)
{
    plcvec_out_reset(h->scratch);
    h->reference.run(h->reference.ctx, v, h->scratch);
    const char *message;
    int status = plcvec_out_status(h->scratch, &message);
    if (status == 1)
        return plcvec_out_skip(out, message);
    if (status == 2)
        return plcvec_out_error(out, message);
    int changed = 0;
    for (size_t s = 0; s < plcvec_out_step_count(h->scratch); s++) {
        int result = plcvec_out_result(h->scratch, s);
        if (target && is(h, "wrong-result") && result != PLCVEC_NONE && !changed)
            result = !result, changed = 1;
        plcvec_out_step(out, result);
        size_t n;
        const plcvec_reported *cells = plcvec_out_cells(h->scratch, s, &n);
        for (size_t i = 0; i < n; i++) {
            const plcvec_reported *c = &cells[i];
            unsigned value = c->value;
            plcvec_type type = (plcvec_type)c->type;
            int compared = c->device >= 0 && listed_unscratched(v, c->device);
            if (target && !changed && compared && type == PLCVEC_WORD) {
                if (is(h, "wrong-result") || is(h, "closes-fds"))
                    value = (value + 1) & 0xFFFF, changed = 1;
                else if (is(h, "out-of-range"))
                    value = 70000, changed = 1;
                else if (is(h, "word-65536"))
                    value = 65536, changed = 1;
            }
            if (target && is(h, "cpu-writes") && c->device >= 0 && strcmp(plcvec_device(c->device)->name, "SD0") == 0)
                continue;       /* written below, as the CPU's own value */
            if (target && !changed && compared && type == PLCVEC_BIT && is(h, "wrong-type"))
                type = PLCVEC_WORD, value = 1, changed = 1;
            if (c->device >= 0)
                plcvec_out_device(out, c->device, type, value);
            else
                plcvec_out_named(out, c->name, type, value);
            if (target && !changed && compared && is(h, "duplicate-write")) {
                /* The same device again, with another value. */
                plcvec_out_device(out, c->device, type, type == PLCVEC_BIT ? !value : (value + 1) & 0xFFFF);
                changed = 1;
            }
        }
        if (is(h, "cpu-writes")) {
            plcvec_out_named(out, "SM56", PLCVEC_BIT, 1);
            plcvec_out_named(out, "SD1", PLCVEC_WORD, 1);
            if (target)
                plcvec_out_named(out, "SD0", PLCVEC_WORD, 1);
        }
        if (target && s == 0 && is(h, "stray-write"))
            plcvec_out_named(out, "D7777", PLCVEC_WORD, 1);
    }
    return 0;
}

/* A process that inherits stdout and stderr and sleeps 300 s, left running. */
static void child_holding_stdout(void)
{
    if (fork() == 0) {
        execlp("sleep", "sleep", "300", (char *)NULL);
        _exit(127);
    }
}

static int run(void *ctx, const plcvec_vector *v, plcvec_out *out)
{
    hostile *h = ctx;
    if (is(h, "skips-everything"))
        return plcvec_out_skip(out, "this implementation skips every vector");
    int target = h->on && strcmp(v->id, h->on) == 0;
    if (target) {
        if (is(h, "closes-fds"))
            for (int fd = 3; fd < 1024; fd++)
                close(fd);      /* what it inherited or the runner opened; then answers wrong */
        if (is(h, "child-holds-stdout"))
            child_holding_stdout();
        if (is(h, "panic"))
            return plcvec_out_error(out, "the implementation failed (a hostile error)");
        if (is(h, "loop-forever"))
            for (volatile unsigned long spin = 0;; spin++)
                ;
        if (is(h, "empty-answer"))
            return 0;
        if (is(h, "exit-zero"))
            exit(0);
        if (is(h, "exit-nonzero"))
            exit(3);
        if (is(h, "crash")) {
            /* A real SIGSEGV (a write to read-only memory), not a raise(); and not a null pointer,
             * which the sanitizers would report and end before the signal is ever delivered. */
            char *volatile text = (char *)"read-only";
            text[0] = 'R';
            raise(SIGSEGV);
        }
    }
    return forward(h, v, out, target);
}

static int supports_nothing(void *ctx, plcvec_instruction instruction)
{
    (void)ctx, (void)instruction;
    return 0;
}

static const char *const kinds[] = {
    "reference", "wrong-result", "panic", "loop-forever", "empty-answer", "stray-write", "duplicate-write",
    "wrong-type", "out-of-range", "exit-zero", "exit-nonzero", "crash", "mutates-request", "supports-nothing",
    "skips-everything", "bad-choice", "cpu-writes", "word-65536", "closes-fds", "child-holds-stdout",
    "follows-alternative", NULL};

/* follows-alternative: the reference following PLCVEC_HOSTILE_CHOICE (ID=alternative) and declaring
 * nothing, a reading followed but not declared. 0, or 2 with a message. */
static int follow_undeclared(plcvec_reference *ref, plcvec_impl *impl)
{
    const char *choice = getenv("PLCVEC_HOSTILE_CHOICE");
    const char *eq = choice ? strchr(choice, '=') : NULL;
    char id[96];
    snprintf(id, sizeof id, "%.*s", eq ? (int)(eq - choice < 90 ? eq - choice : 90) : 0, choice ? choice : "");
    if (!eq || plcvec_reference_choose(ref, id, eq + 1) != 0) {
        fprintf(stderr, "hostile: PLCVEC_HOSTILE_CHOICE=%s: ID=alternative of the suite\n", choice ? choice : "");
        return 2;
    }
    impl->choices = NULL, impl->n_choices = 0;
    return 0;
}

int main(int argc, char **argv)
{
    static plcvec_reference ref;
    plcvec_reference_init(&ref);
    hostile h = {0};
    h.kind = getenv("PLCVEC_HOSTILE") && *getenv("PLCVEC_HOSTILE") ? getenv("PLCVEC_HOSTILE") : "reference";
    h.on = getenv("PLCVEC_HOSTILE_ON");
    const char *const *k = kinds;
    while (*k && strcmp(*k, h.kind) != 0)
        k++;
    if (!*k) {
        fprintf(stderr, "hostile: PLCVEC_HOSTILE=%s: no such implementation; known:", h.kind);
        for (k = kinds; *k; k++)
            fprintf(stderr, "%s %s", k == kinds ? "" : ",", *k);
        fprintf(stderr, "\n");
        return 2;
    }
    h.reference = plcvec_reference_impl(&ref);
    h.scratch = plcvec_out_new();
    plcvec_impl impl = h.reference;
    if (is(&h, "follows-alternative") && follow_undeclared(&ref, &impl) != 0)
        return 2;
    /* The reference itself is run as the README shows; every other one wraps it. `mutates-request`
     * is the reference too: the request is const data (read-only memory), which the interface gives
     * an implementation no way to change. */
    if (!is(&h, "reference") && !is(&h, "mutates-request") && !is(&h, "follows-alternative")) {
        impl.name = h.kind;
        impl.ctx = &h;
        impl.run = run;
    }
    if (is(&h, "supports-nothing"))
        impl.supports = supports_nothing;
    static const char *const cpu[] = {"SM56", "SD1", "SD0", NULL};
    if (is(&h, "cpu-writes"))
        impl.cpu_writes = cpu;
    /* bad-choice: a declaration by name, the way a test program's command line declares one. */
    char **args = malloc(((size_t)argc + 3) * sizeof *args);
    if (!args)
        return 2;
    int n = 0;
    for (int i = 0; i < argc; i++)
        args[n++] = argv[i];
    if (is(&h, "bad-choice")) {
        args[n++] = "--choose";
        args[n++] = "NO-SUCH-INTERPRETATION=x";
    }
    args[n] = NULL;
    int rc = plcvec_main(&impl, NULL, 0, n, args);
    free(args);
    plcvec_out_free(h.scratch);
    return rc;
}
