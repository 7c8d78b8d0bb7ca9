"""The seeded generator the golden random vectors are drawn with: SplitMix64, in plain integers.

The golden set must be the same for ever from the same seed, whatever Python or library version
draws it. Python guarantees only that `random.Random(seed).random()` keeps its sequence; its
integer helpers (`randrange`, `choice`, `getrandbits` through them) have changed between versions,
and hypothesis may draw differently in any release. SplitMix64 (Steele, Lea and Flood, "Fast
splittable pseudorandom number generators", OOPSLA 2014; the seeder of Java's SplittableRandom and of
the xoshiro generators) is a few lines of 64-bit arithmetic, fully specified here, so its sequence
depends on nothing but the seed. tests/test_prng.py checks it against the published sequence.
"""

MASK64 = (1 << 64) - 1
GOLDEN_GAMMA = 0x9E3779B97F4A7C15


class SplitMix64:
    def __init__(self, seed):
        self.state = seed & MASK64

    def next64(self):
        """The next 64-bit output."""
        self.state = (self.state + GOLDEN_GAMMA) & MASK64
        z = self.state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK64
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK64
        return z ^ (z >> 31)

    def below(self, n):
        """A uniform integer in [0, n), by rejection (no modulo bias): the top bits of each output,
        redrawn while they fall in the incomplete last block."""
        if not 0 < n <= 1 << 64:
            raise ValueError(f"below({n}): n must be in 1..2**64")
        bits = max(1, (n - 1).bit_length())
        while True:
            value = self.next64() >> (64 - bits)
            if value < n:
                return value

    def integer(self, lo, hi):
        """A uniform integer in [lo, hi]."""
        return lo + self.below(hi - lo + 1)

    def boolean(self):
        return self.next64() >> 63 == 1

    def choice(self, items):
        return items[self.below(len(items))]
