/* The reference's device memory: the vector's devices, addressed by name or by base + offset
 * ("D100" + 2 is D102), with the sizes the vector assumes. Knows nothing about any instruction. */
#ifndef PLCVEC_REFERENCE_MEMORY_H
#define PLCVEC_REFERENCE_MEMORY_H

#include "plcvec/plcvec.h"

#define MEMORY_CELLS 64

typedef struct mem_cell {
    int device;                 /* plcvec_device_id, or -1 for a device outside the table */
    const char *kind;           /* static: the table's, or an operand's */
    int32_t number;
    uint8_t type;
    uint16_t value;
} mem_cell;

/* An address: a device type and a number (P_EQ and other flags have number -1). */
typedef struct address {
    const char *kind;
    int32_t number;
    int device;                 /* its plcvec_device_id when known, else -1 */
} address;

typedef struct memory {
    const plcvec_vector *vector;
    mem_cell cells[MEMORY_CELLS];
    size_t n;
    int overflow;
} memory;

void memory_load(memory *m, const plcvec_vector *v);
address memory_device(int device);
address memory_offset(address base, int offset);
/* 1 when base .. base+words-1 all exist (a device type whose size the vector does not state is
 * taken to exist). */
int memory_in_range(const memory *m, address base, int words);
uint16_t memory_read(const memory *m, address a);           /* 0 when never written */
void memory_write(memory *m, address a, plcvec_type type, uint16_t value);
void memory_write_named(memory *m, int device, plcvec_type type, uint16_t value);
/* A device by name ("SD0"), looked up once into *cache (start it at -1). By name rather than as a
 * generated PLCVEC_DEV_ constant: the table of names holds the devices the exported vectors name,
 * and a vector set without TADD vectors names no SD0. */
static inline int memory_device_named(const char *name, int *cache)
{
    if (*cache < 0)
        *cache = plcvec_device_intern(name);
    return *cache;
}
int16_t to_signed16(uint16_t word);     /* a word read as "16-bit signed binary" */
/* Report every device (scratch included: never compared) after a step. */
void memory_report(const memory *m, plcvec_out *out, int result);

#endif
