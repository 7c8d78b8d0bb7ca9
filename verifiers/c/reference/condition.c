/* The condition an instruction compares with, from the generated values (plcvec_instructions[]),
 * never from its mnemonic: "LDTM<=" and "AND <=DT" are both PLCVEC_CONDITION_LE. */
#include "condition.h"

int condition_holds(plcvec_condition condition, int order)
{
    switch (condition) {
    case PLCVEC_CONDITION_EQ: return order == 0;
    case PLCVEC_CONDITION_NE: return order != 0;
    case PLCVEC_CONDITION_LT: return order < 0;
    case PLCVEC_CONDITION_LE: return order <= 0;
    case PLCVEC_CONDITION_GT: return order > 0;
    case PLCVEC_CONDITION_GE: return order >= 0;
    default: return 0;
    }
}
