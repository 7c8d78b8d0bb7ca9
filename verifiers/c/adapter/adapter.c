/* plcvec-c-reference-adapter: the C reference served over the stdio protocol (PROTOCOL.md), so
 * that `plcvec verify --adapter verifiers/c/reference-adapter` judges it like any other.
 *
 *   plcvec-c-reference-adapter [--mutant NAME] [--choose ID=ALT]...
 *
 * Each request is turned into a plcvec_vector and run by the same code the in-process tests run.
 * The wire is read with cJSON (only here: the library itself reads no JSON). Bad input never
 * crashes it: a line that is not JSON or a hello of another protocol is answered with `fatal`; a
 * vector it cannot read is answered with `error` naming what is wrong. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "reference.h"

#define PROTOCOL 1

static void emit(cJSON *msg)
{
    char *text = cJSON_PrintUnformatted(msg);
    if (text) {
        fputs(text, stdout);
        fputc('\n', stdout);
        free(text);
    }
    cJSON_Delete(msg);
}

static int fatal(const char *fmt, ...)
{
    char message[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(message, sizeof message, fmt, ap);
    va_end(ap);
    cJSON *msg = cJSON_CreateObject();
    cJSON_AddStringToObject(msg, "type", "fatal");
    cJSON_AddStringToObject(msg, "message", message);
    emit(msg);
    fflush(stdout);
    fprintf(stderr, "plcvec-c-reference-adapter: %s\n", message);
    return 2;
}

/* ---- hello ------------------------------------------------------------------------------- */

static int family_named(const char *name)
{
    for (int f = 0; f < PLCVEC_FAMILY_COUNT; f++)
        if (strcmp(plcvec_family_names[f], name) == 0)
            return f;
    return -1;
}

static int instruction_named(const char *name)
{
    for (int i = 0; i < PLCVEC_INSTRUCTION_COUNT; i++)
        if (strcmp(plcvec_instruction_names[i], name) == 0)
            return i;
    return -1;
}

static cJSON *hello(const plcvec_reference *ref, const char *name, const cJSON *request)
{
    cJSON *answer = cJSON_CreateObject();
    cJSON_AddStringToObject(answer, "type", "hello");
    cJSON_AddNumberToObject(answer, "protocol", PROTOCOL);
    cJSON *adapter = cJSON_AddObjectToObject(answer, "adapter");
    cJSON_AddStringToObject(adapter, "name", name);
    cJSON_AddStringToObject(adapter, "version", PLCVEC_SUITE_VERSION);
    cJSON *instructions = cJSON_AddArrayToObject(answer, "instructions");
    cJSON *interps = cJSON_AddObjectToObject(answer, "interpretations");
    uint32_t families = 0;
    const cJSON *fams = cJSON_GetObjectItemCaseSensitive(request, "families");
    const cJSON *fam;
    cJSON_ArrayForEach(fam, fams) {
        int f = fam->string ? family_named(fam->string) : -1;
        if (f >= 0)
            families |= 1u << f;
    }
    for (int i = 0; i < PLCVEC_INSTRUCTION_COUNT; i++)
        if (families >> plcvec_instruction_family[i] & 1)
            cJSON_AddItemToArray(instructions, cJSON_CreateString(plcvec_instruction_names[i]));
    for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
        if (plcvec_interpretations[i].families & families)
            cJSON_AddStringToObject(interps, plcvec_interpretations[i].id,
                                    plcvec_interpretations[i].alternatives[ref->declared[i]]);
    return answer;
}

/* ---- one vector of a run request -------------------------------------------------------- */

/* The vector being built; every list is malloc'd and freed once answered. */
typedef struct building {
    plcvec_vector v;
    plcvec_cell *devices, *sets;
    uint16_t *scratch;
    plcvec_operand *operands;
    plcvec_size *sizes;
    plcvec_step *steps;
    plcvec_clock *clocks;
    char problem[300];
} building;

static int fail(building *b, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(b->problem, sizeof b->problem, fmt, ap);
    va_end(ap);
    return -1;
}

static int device_of(building *b, const char *name)
{
    int d = plcvec_device_intern(name);     /* a device the compiled suite does not name is added */
    if (d < 0)
        fail(b, "device name '%.60s' is longer than 23 characters", name);
    return d;
}

/* A device value: a bit (true/false) or a word (an integer 0..65535). */
static int cell_of(building *b, const cJSON *item, plcvec_cell *cell)
{
    int d = device_of(b, item->string);
    if (d < 0)
        return -1;
    cell->device = (uint16_t)d;
    if (cJSON_IsBool(item)) {
        cell->type = PLCVEC_BIT;
        cell->value = cJSON_IsTrue(item) ? 1 : 0;
        return 0;
    }
    if (!cJSON_IsNumber(item) || item->valuedouble != (double)(long)item->valuedouble || item->valuedouble < 0 ||
        item->valuedouble > 65535)
        return fail(b, "%.60s: a device value is true, false or an integer 0..65535", item->string);
    cell->type = PLCVEC_WORD;
    cell->value = (uint16_t)item->valuedouble;
    return 0;
}

static int cells_of(building *b, const cJSON *obj, plcvec_cell *into, uint16_t *n)
{
    const cJSON *item;
    cJSON_ArrayForEach(item, obj) {
        if (cell_of(b, item, &into[*n]) < 0)
            return -1;
        (*n)++;
    }
    return 0;
}

static int8_t flag_of(const cJSON *step, const char *key)
{
    const cJSON *x = cJSON_GetObjectItemCaseSensitive(step, key);
    return x ? (int8_t)(cJSON_IsTrue(x) ? 1 : 0) : (int8_t)PLCVEC_NONE;
}

/* initial.scratch, initial.operands and assumes.device_sizes. */
static int initial_of(building *b, const cJSON *scratch, const cJSON *operands, const cJSON *sizes)
{
    plcvec_vector *v = &b->v;
    const cJSON *item;
    cJSON_ArrayForEach(item, scratch) {
        int d = cJSON_IsString(item) ? device_of(b, item->valuestring) : fail(b, "scratch lists device names");
        if (d < 0)
            return -1;
        b->scratch[v->n_scratch++] = (uint16_t)d;
    }
    v->scratch = b->scratch;
    cJSON_ArrayForEach(item, operands) {
        plcvec_operand *op = &b->operands[v->n_operands];
        const cJSON *dev = cJSON_GetObjectItemCaseSensitive(item, "device");
        const cJSON *k = cJSON_GetObjectItemCaseSensitive(item, "constant");
        op->name = item->string;
        if (cJSON_IsString(dev)) {
            int d = device_of(b, dev->valuestring);
            if (d < 0)
                return -1;
            op->device = (uint16_t)d;
        } else if (cJSON_IsNumber(k) && k->valuedouble >= -2147483648.0 && k->valuedouble <= 2147483647.0) {
            op->is_constant = 1;
            op->constant = (int32_t)k->valuedouble;
        } else
            return fail(b, "operand %.20s is {\"device\": NAME} or {\"constant\": N}", item->string);
        v->n_operands++;
    }
    v->operands = b->operands;
    cJSON_ArrayForEach(item, sizes) {
        if (!cJSON_IsNumber(item) || item->valuedouble < 0)
            return fail(b, "device_sizes holds counts of points");
        b->sizes[v->n_sizes].kind = item->string;
        b->sizes[v->n_sizes++].points = (uint32_t)item->valuedouble;
    }
    v->sizes = b->sizes;
    return 0;
}

/* A step's clock: the fields it gives, each marked in `fields`. */
static const plcvec_clock *clock_of(const cJSON *clock, plcvec_clock *c)
{
    static const char *const clock_keys[6] = {"year", "month", "day", "hour", "minute", "second"};
    if (!cJSON_IsObject(clock))
        return NULL;
    int32_t *fields[6] = {&c->year, &c->month, &c->day, &c->hour, &c->minute, &c->second};
    for (int k = 0; k < 6; k++) {
        const cJSON *x = cJSON_GetObjectItemCaseSensitive(clock, clock_keys[k]);
        if (cJSON_IsNumber(x) && x->valuedouble > -1e9 && x->valuedouble < 1e9) {
            c->fields |= (uint8_t)(1 << k);
            *fields[k] = (int32_t)x->valuedouble;
        }
    }
    return c;
}

/* The steps' inputs and `set`s (a request carries no expectation). */
static int steps_of(building *b, const cJSON *steps)
{
    size_t s = 0, set_at = 0;
    const cJSON *step;
    cJSON_ArrayForEach(step, steps) {
        plcvec_step *st = &b->steps[s];
        st->rlo_in = flag_of(step, "rlo_in");
        st->en = flag_of(step, "en");
        st->input = flag_of(step, "input");
        const cJSON *elapsed = cJSON_GetObjectItemCaseSensitive(step, "elapsed_ms");
        st->elapsed_ms = cJSON_IsNumber(elapsed) && elapsed->valuedouble >= 0 && elapsed->valuedouble < 9e15
                             ? (int64_t)elapsed->valuedouble : PLCVEC_NONE;
        st->clock = clock_of(cJSON_GetObjectItemCaseSensitive(step, "clock"), &b->clocks[s]);
        st->set = b->sets + set_at;
        if (cells_of(b, cJSON_GetObjectItemCaseSensitive(step, "set"), b->sets + set_at, &st->n_set) < 0)
            return -1;
        set_at += st->n_set;
        st->expect.result = PLCVEC_NONE;
        s++;
    }
    b->v.steps = b->steps;
    b->v.n_steps = (uint16_t)s;
    return 0;
}

/* Room for the request's lists; 0, or -1 (answered) when it is too large or out of memory. */
static int allocate(building *b, const cJSON *devices, const cJSON *operands, const cJSON *scratch, const cJSON *sizes,
                    const cJSON *steps)
{
    int n_dev = cJSON_GetArraySize(devices), n_steps = cJSON_GetArraySize(steps), n_set = 0;
    const cJSON *step;
    cJSON_ArrayForEach(step, steps) {
        if (!cJSON_IsObject(step))
            return fail(b, "every step is an object");
        n_set += cJSON_GetArraySize(cJSON_GetObjectItemCaseSensitive(step, "set"));
    }
    if (n_steps == 0 || n_steps > 65535 || n_dev > 65535 || n_set > 65535)
        return fail(b, "a vector has 1 to 65535 steps");
    b->devices = calloc((size_t)n_dev + 1, sizeof *b->devices);
    b->sets = calloc((size_t)n_set + 1, sizeof *b->sets);
    b->operands = calloc((size_t)cJSON_GetArraySize(operands) + 1, sizeof *b->operands);
    b->scratch = calloc((size_t)cJSON_GetArraySize(scratch) + 1, sizeof *b->scratch);
    b->sizes = calloc((size_t)cJSON_GetArraySize(sizes) + 1, sizeof *b->sizes);
    b->steps = calloc((size_t)n_steps, sizeof *b->steps);
    b->clocks = calloc((size_t)n_steps, sizeof *b->clocks);
    if (!b->devices || !b->sets || !b->operands || !b->scratch || !b->sizes || !b->steps || !b->clocks)
        return fail(b, "out of memory");
    return 0;
}

static int build(building *b, const cJSON *req)
{
    plcvec_vector *v = &b->v;
    const cJSON *family = cJSON_GetObjectItemCaseSensitive(req, "family");
    const cJSON *instruction = cJSON_GetObjectItemCaseSensitive(req, "instruction");
    const cJSON *initial = cJSON_GetObjectItemCaseSensitive(req, "initial");
    const cJSON *devices = cJSON_GetObjectItemCaseSensitive(initial, "devices");
    const cJSON *operands = cJSON_GetObjectItemCaseSensitive(initial, "operands");
    const cJSON *scratch = cJSON_GetObjectItemCaseSensitive(initial, "scratch");
    const cJSON *steps = cJSON_GetObjectItemCaseSensitive(req, "steps");
    const cJSON *sizes = cJSON_GetObjectItemCaseSensitive(cJSON_GetObjectItemCaseSensitive(req, "assumes"), "device_sizes");
    if (!cJSON_IsString(family) || !cJSON_IsString(instruction) || !cJSON_IsObject(devices) ||
        !cJSON_IsObject(operands) || !cJSON_IsArray(steps))
        return fail(b, "the request needs family, instruction, initial.devices, initial.operands and steps");
    int f = family_named(family->valuestring), ins = instruction_named(instruction->valuestring);
    if (f < 0 || ins < 0 || (int)plcvec_instruction_family[ins] != f)
        return fail(b, "unknown family or instruction: %.60s %.60s", family->valuestring, instruction->valuestring);
    v->family = (plcvec_family)f;
    v->instruction = (plcvec_instruction)ins;
    v->description = "";
    if (allocate(b, devices, operands, scratch, sizes, steps) < 0 || cells_of(b, devices, b->devices, &v->n_devices) < 0)
        return -1;
    v->devices = b->devices;
    if (initial_of(b, scratch, operands, sizes) < 0)
        return -1;
    return steps_of(b, steps);
}

static void release(building *b)
{
    free(b->devices);
    free(b->sets);
    free(b->scratch);
    free(b->operands);
    free(b->sizes);
    free(b->steps);
    free(b->clocks);
}

static cJSON *run_one(const plcvec_impl *impl, plcvec_out *out, const cJSON *req)
{
    cJSON *result = cJSON_CreateObject();
    cJSON_AddStringToObject(result, "type", "result");
    const cJSON *id = cJSON_GetObjectItemCaseSensitive(req, "id");
    cJSON_AddStringToObject(result, "id", cJSON_IsString(id) ? id->valuestring : "");
    building b;
    memset(&b, 0, sizeof b);
    b.v.id = cJSON_IsString(id) ? id->valuestring : "";
    if (build(&b, req) < 0) {
        cJSON_AddStringToObject(result, "error", b.problem);
        release(&b);
        return result;
    }
    plcvec_out_reset(out);
    impl->run(impl->ctx, &b.v, out);
    const char *message;
    int status = plcvec_out_status(out, &message);
    if (status == 1)
        cJSON_AddStringToObject(result, "skip", message);
    else if (status != 0)
        cJSON_AddStringToObject(result, "error", message);
    else {
        cJSON *steps = cJSON_AddArrayToObject(result, "steps");
        for (size_t s = 0; s < plcvec_out_step_count(out); s++) {
            cJSON *step = cJSON_CreateObject();
            int r = plcvec_out_result(out, s);
            if (r != PLCVEC_NONE)
                cJSON_AddBoolToObject(step, "result", r);
            cJSON *devs = cJSON_AddObjectToObject(step, "devices");
            size_t n;
            const plcvec_reported *cells = plcvec_out_cells(out, s, &n);
            for (size_t i = 0; i < n; i++) {
                const char *name = cells[i].device >= 0 ? plcvec_device(cells[i].device)->name : cells[i].name;
                if (cells[i].type == PLCVEC_BIT)
                    cJSON_AddBoolToObject(devs, name, cells[i].value != 0);
                else
                    cJSON_AddNumberToObject(devs, name, cells[i].value);
            }
            cJSON_AddItemToArray(steps, step);
        }
    }
    release(&b);
    return result;
}

/* ---- the loop ------------------------------------------------------------------------------ */

/* The command line: --mutant NAME, --choose ID=ALT; 0, or 2 after saying what is wrong. */
static int options(int argc, char **argv, plcvec_reference *ref, char *name, size_t size)
{
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--mutant") == 0 && i + 1 < argc) {
            const plcvec_mutant *m = plcvec_mutant_named(argv[++i]);
            if (!m) {
                fprintf(stderr, "plcvec-c-reference-adapter: no mutant '%s'; known:", argv[i]);
                for (size_t k = 0; k < plcvec_mutant_count; k++)
                    fprintf(stderr, " %s", plcvec_mutants[k].name);
                fprintf(stderr, "\n");
                return 2;
            }
            m->apply(ref);
            snprintf(name, size, "plcvec-c-reference (mutant %s)", m->name);
        } else if (strcmp(argv[i], "--choose") == 0 && i + 1 < argc) {
            char choice[256];
            snprintf(choice, sizeof choice, "%s", argv[++i]);
            char *eq = strchr(choice, '=');
            if (!eq || (*eq = '\0', plcvec_reference_choose(ref, choice, eq + 1) != 0)) {
                fprintf(stderr, "plcvec-c-reference-adapter: --choose %s: not an ID=ALTERNATIVE of the suite\n", argv[i]);
                return 2;
            }
        } else {
            fprintf(stderr, "usage: plcvec-c-reference-adapter [--mutant NAME] [--choose ID=ALT]...\n");
            return 2;
        }
    }
    return 0;
}

/* One message of the protocol: 0 to go on, 1 at `bye`, or the status of a fatal answer. */
static int answer(const cJSON *msg, long number, plcvec_reference *ref, const char *name, const plcvec_impl *impl,
                  plcvec_out *out)
{
    const cJSON *type = cJSON_GetObjectItemCaseSensitive(msg, "type");
    if (!msg || !cJSON_IsString(type))
        return fatal("input line %ld is not a JSON object with a \"type\"", number);
    if (strcmp(type->valuestring, "hello") == 0) {
        const cJSON *protocol = cJSON_GetObjectItemCaseSensitive(msg, "protocol");
        if (!cJSON_IsNumber(protocol) || protocol->valuedouble != PROTOCOL)
            return fatal("this adapter speaks protocol %d, not %s", PROTOCOL,
                         cJSON_IsNumber(protocol) ? "another" : "(none given)");
        emit(hello(ref, name, msg));
    } else if (strcmp(type->valuestring, "run") == 0) {
        const cJSON *vectors = cJSON_GetObjectItemCaseSensitive(msg, "vectors");
        if (!cJSON_IsArray(vectors))
            return fatal("input line %ld: a run request holds \"vectors\", a list", number);
        const cJSON *req;
        cJSON_ArrayForEach(req, vectors)
            emit(run_one(impl, out, req));
    } else if (strcmp(type->valuestring, "bye") == 0)
        return 1;
    else
        return fatal("input line %ld: unknown message type \"%.40s\"", number, type->valuestring);
    fflush(stdout);     /* once per message: a run's batch is answered whole */
    return 0;
}

int main(int argc, char **argv)
{
    static plcvec_reference ref;
    plcvec_reference_init(&ref);
    char name[128] = "plcvec-c-reference";
    if (options(argc, argv, &ref, name, sizeof name) != 0)
        return 2;
    plcvec_impl impl = plcvec_reference_impl(&ref);
    plcvec_out *out = plcvec_out_new();
    if (!out)
        return fatal("out of memory");
    char *line = NULL;
    size_t cap = 0;
    long number = 0;
    int rc = 0;
    for (;;) {
        ssize_t len = getline(&line, &cap, stdin);
        if (len < 0)
            break;      /* end of input means bye */
        number++;
        if (strspn(line, " \t\r\n") == (size_t)len)
            continue;
        cJSON *msg = cJSON_ParseWithLength(line, (size_t)len);
        rc = answer(msg, number, &ref, name, &impl, out);
        cJSON_Delete(msg);
        if (rc != 0)
            break;
    }
    free(line);
    plcvec_out_free(out);
    return rc == 1 ? 0 : rc;
}
