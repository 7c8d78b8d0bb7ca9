/* A minimal emulator checked against plcvec: the FX5 TADD/TADDP instruction on a memory of its
 * own, plugged in with the "execute on my memory" helper. Run it as a test program:
 *
 *   ./tadd_emulator --family fx5-time-add            (every TADD/TADDP vector)
 *   ./tadd_emulator --id 'fx5-time-add/TADDP*'       (a glob of ids)
 */
#include <stdio.h>
#include <string.h>

#include "plcvec/plcvec.h"

/* The emulator: a small device memory and the TADD/TADDP state. */
typedef struct cell {
    char name[16];
    unsigned value;
} cell;

typedef struct emulator {
    cell mem[64];
    int n;
    long d_points;      /* the number of D devices of the CPU model */
    int previous_en;    /* TADDP's edge */
} emulator;

static cell *find(emulator *e, const char *name, int create)
{
    for (int i = 0; i < e->n; i++)
        if (strcmp(e->mem[i].name, name) == 0)
            return &e->mem[i];
    if (!create || e->n == 64)
        return NULL;
    snprintf(e->mem[e->n].name, sizeof e->mem[e->n].name, "%s", name);
    e->mem[e->n].value = 0;
    return &e->mem[e->n++];
}

static unsigned get(emulator *e, const char *kind, long n)
{
    char name[16];
    snprintf(name, sizeof name, "%s%ld", kind, n);
    cell *c = find(e, name, 0);
    return c ? c->value : 0;
}

static void put(emulator *e, const char *kind, long n, unsigned value)
{
    char name[16];
    snprintf(name, sizeof name, "%s%ld", kind, n);
    cell *c = find(e, name, 1);
    if (c)
        c->value = value;
}

/* TADD (s1) + (s2) -> (d): three words h, m, s each; wraps at 24:00:00 with the carry flags. */
static void tadd(emulator *e, long s1, long s2, long d)
{
    if (s1 + 3 > e->d_points || s2 + 3 > e->d_points || d + 3 > e->d_points) {
        put(e, "SD", 0, 0x2820), put(e, "SD", 8067, 0x2820);      /* device range error */
        return;
    }
    long a[3], b[3];
    for (int i = 0; i < 3; i++) {
        a[i] = (short)get(e, "D", s1 + i), b[i] = (short)get(e, "D", s2 + i);
        long hi = i == 0 ? 23 : 59;
        if (a[i] < 0 || a[i] > hi || b[i] < 0 || b[i] > hi) {
            put(e, "SD", 0, 0x3405), put(e, "SD", 8067, 0x3405);  /* value range error */
            return;
        }
    }
    long sum = (a[0] + b[0]) * 3600 + (a[1] + b[1]) * 60 + a[2] + b[2];
    long t = sum % 86400;
    put(e, "D", d, (unsigned)(t / 3600)), put(e, "D", d + 1, (unsigned)(t / 60 % 60)), put(e, "D", d + 2, (unsigned)(t % 60));
    put(e, "SM", 700, sum >= 86400), put(e, "SM", 8022, sum >= 86400), put(e, "SM", 8020, t == 0);
}

/* ---- the plcvec helper's five functions ---- */

static int supports(void *ctx, plcvec_instruction i)
{
    (void)ctx;
    return i == PLCVEC_INSTR_TADD || i == PLCVEC_INSTR_TADDP;
}

static int reset(void *ctx, const plcvec_vector *v)
{
    emulator *e = ctx;
    e->n = 0;
    e->previous_en = 0;
    e->d_points = plcvec_size_of(v, "D");
    return 0;
}

static void write_device(void *ctx, const char *device, plcvec_type type, unsigned value)
{
    (void)type;
    cell *c = find(ctx, device, 1);
    if (c)
        c->value = value;
}

static unsigned read_device(void *ctx, const char *device)
{
    cell *c = find(ctx, device, 0);
    return c ? c->value : 0;
}

static long number(const plcvec_vector *v, const char *operand)
{
    return plcvec_devices[plcvec_operand_named(v, operand)->device].number;     /* "D100" -> 100 */
}

static int execute(void *ctx, const plcvec_vector *v, const plcvec_step *step)
{
    emulator *e = ctx;
    int en = step->en == 1;
    int run = plcvec_instructions[v->instruction].execution == PLCVEC_EXECUTION_RISING_EDGE ? en && !e->previous_en : en;
    e->previous_en = en;
    if (run)
        tadd(e, number(v, "s1"), number(v, "s2"), number(v, "d"));
    return PLCVEC_NONE;     /* not a contact */
}

static void written(void *ctx, void (*seen)(void *, const char *, plcvec_type, unsigned), void *arg)
{
    emulator *e = ctx;
    for (int i = 0; i < e->n; i++)
        seen(arg, e->mem[i].name, strncmp(e->mem[i].name, "SM", 2) == 0 ? PLCVEC_BIT : PLCVEC_WORD, e->mem[i].value);
}

int main(int argc, char **argv)
{
    static emulator e;
    plcvec_machine m = {0};
    m.name = "tadd-emulator";
    m.ctx = &e;
    m.supports = supports;
    m.reset = reset;
    m.write = write_device;
    m.read = read_device;
    m.execute = execute;
    m.written = written;
    plcvec_impl impl = plcvec_machine_impl(&m);
    return plcvec_main(&impl, NULL, 0, argc, argv);
}
