package plcvec

// A run reads, vector after vector, what Prepare made of each: the request's device keys,
// initial values, operands and steps, and the expected state after every step. Made one small
// allocation at a time, these lie scattered over the heap, and a pass spends much of its time
// waiting for memory. arena lays them out instead in a few large arrays, in the order of the
// vectors, so that a pass reads memory front to back (which the processor prefetches), and
// interns the strings a CPU compares (family, instruction, operand and device kinds) so that
// each is one copy, read often and so kept in cache.
type arena struct {
	chunk  int // elements per array; 0: each piece its own allocation (a lone request)
	values slab[Value]
	// befores are read only for a failure's message: apart from the values a pass reads
	befores slab[Value]
	keys    slab[uint64]
	addrs   slab[Address]
	slots   slab[uint16]
	runs    slab[uint16]
	// operandAddrs apart from addrs: a CPU reads its operands' addresses, rarely the devices'
	operandAddrs slab[Address]
	devices      slab[Device]
	flags        slab[bool]
	results      slab[Result]
	inputs       slab[Inputs]
	operands     slab[namedOperand]
	sizes        slab[kindSize]
	ints         slab[int]
	requests     slab[Request]
	expects      slab[expected]
	cases        slab[Case]
	names        slab[string]
	strings      map[string]string // nil: no interning
	parsed       []Address         // a request's addresses while its keys are worked out
}

// runArena is the arena of a whole run's preparation.
func runArena() *arena {
	return &arena{chunk: 4096, strings: map[string]string{}}
}

// slab hands out consecutive pieces of one array, starting a new array when it runs out.
type slab[T any] struct{ free []T }

func (s *slab[T]) take(n, chunk int) []T {
	if len(s.free) < n {
		s.free = make([]T, max(n, chunk))
	}
	out := s.free[:n:n]
	s.free = s.free[n:]
	return out
}

// one is a single element of the slab, for a struct a run reads for every vector.
func (s *slab[T]) one(chunk int) *T { return &s.take(1, chunk)[0] }

// intern is the one copy of s that the arena keeps.
func (a *arena) intern(s string) string {
	if a.strings == nil {
		return s
	}
	if t, ok := a.strings[s]; ok {
		return t
	}
	a.strings[s] = s
	return s
}
