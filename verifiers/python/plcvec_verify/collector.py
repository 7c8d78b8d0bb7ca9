"""The cyclic garbage collector held off while a large tree of plain values is built.

Loading a vector set, planning a run over it and building a golden set allocate hundreds of
thousands of dicts and lists and keep nearly all of them: with the collector on, each of the many
collections those allocations trigger walks the same live objects again (a quarter of
`plcvec verify`'s CPU time before it runs a vector, a seventh of a golden build), to find the few
reference cycles (closures, exceptions), which a later pass frees all the same.
"""

from __future__ import annotations

import gc
from contextlib import contextmanager


@contextmanager
def collector_paused():
    """Hold the collector off inside the block; nested blocks leave it to the outermost.

    What the block made is then moved to the oldest generation without a pass over it (freeze, then
    unfreeze): enabled with all of it still in the youngest, the collector's next allocation would
    traverse every object the block kept (a thirtieth of a golden build). The oldest generation is
    still collected, when enough survives after it. Not when the caller froze objects of its own:
    unfreeze would hand those back to the collector.
    """
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            if not gc.get_freeze_count():
                gc.freeze()
                gc.unfreeze()
            gc.enable()
