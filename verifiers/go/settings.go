package plcvec

import (
	"fmt"
	"math"
	"os"
	"strconv"
	"strings"
	"time"
)

// The environment variables every plcvec runner reads, with the same meaning and the same
// errors (CONTRACT.md): `plcvec verify` takes them as the defaults of its flags, and Run reads
// them so that a CI job changes what a gate runs without changing the test.
const (
	EnvVectors           = "PLCVEC_VECTORS"            // another copy of the vectors (a folder)
	EnvID                = "PLCVEC_ID"                 // ids or globs, comma-separated
	EnvFamily            = "PLCVEC_FAMILY"             // families, comma-separated
	EnvInstruction       = "PLCVEC_INSTRUCTION"        // instructions, comma-separated
	EnvTag               = "PLCVEC_TAG"                // tags, comma-separated
	EnvInterpretation    = "PLCVEC_INTERPRETATION"     // interpretations, comma-separated
	EnvShard             = "PLCVEC_SHARD"              // K/N
	EnvKnownFailures     = "PLCVEC_KNOWN_FAILURES"     // a known-failures TOML file
	EnvWriteExpectations = "PLCVEC_WRITE_EXPECTATIONS" // write the run's failures to this TOML file
	EnvTimeout           = "PLCVEC_TIMEOUT"            // seconds per vector
)

// DefaultTimeout bounds one vector when $PLCVEC_TIMEOUT does not: an implementation that never
// answers is reported against that vector, and the run ends there rather than hang.
const DefaultTimeout = 10 * time.Second

// environment is what the PLCVEC_* variables ask of a run.
type environment struct {
	narrow   Selection // narrows the selection the code gives (both must take a vector)
	narrowed bool
	known    string
	write    string
	timeout  time.Duration
}

// readEnvironment reads the PLCVEC_* variables. A malformed value is an error naming its
// variable; an empty item of a list (PLCVEC_FAMILY=,) is an error too, never "no filter".
func readEnvironment() (environment, error) {
	env := environment{known: os.Getenv(EnvKnownFailures), write: os.Getenv(EnvWriteExpectations)}
	lists := []struct {
		name string
		into *[]string
	}{{EnvID, &env.narrow.IDs}, {EnvFamily, &env.narrow.Families}, {EnvInstruction, &env.narrow.Instructions},
		{EnvTag, &env.narrow.Tags}, {EnvInterpretation, &env.narrow.Interpretations}}
	for _, l := range lists {
		text, ok := os.LookupEnv(l.name)
		if !ok || text == "" {
			continue
		}
		items := strings.Split(text, ",")
		for i := range items {
			items[i] = strings.TrimSpace(items[i])
			if items[i] == "" {
				return env, fmt.Errorf("%s=%q: an empty name in the list (names are separated by commas)", l.name, text)
			}
		}
		*l.into, env.narrowed = items, true
	}
	if text := os.Getenv(EnvShard); text != "" {
		shard, err := ParseShard(text)
		if err != nil {
			return env, fmt.Errorf("%s=%q: %v", EnvShard, text, err)
		}
		env.narrow.Shard, env.narrowed = shard, true
	}
	var err error
	env.timeout, err = parseTimeout(os.Getenv(EnvTimeout))
	return env, err
}

// parseTimeout reads $PLCVEC_TIMEOUT: seconds, a positive finite number; "" is the default.
func parseTimeout(text string) (time.Duration, error) {
	if text == "" {
		return DefaultTimeout, nil
	}
	s, err := strconv.ParseFloat(strings.TrimSpace(text), 64)
	if err != nil || !(s > 0) || math.IsInf(s, 0) || s > 1e6 {
		return 0, fmt.Errorf("%s=%q: seconds per vector, a positive number (default %d)", EnvTimeout, text, int(DefaultTimeout/time.Second))
	}
	return time.Duration(s * float64(time.Second)), nil
}

// narrow keeps the vectors the PLCVEC_* selection also takes.
func (s *Suite) narrow(vectors []*Vector, env environment) ([]*Vector, error) {
	if err := s.checkEnvironment(env); err != nil {
		return nil, err
	}
	out := vectors[:0:0]
	for _, v := range vectors {
		if env.narrow.Matches(v) {
			out = append(out, v)
		}
	}
	return out, nil
}

// checkEnvironment checks each variable's names against the suite apart, so that an error names
// the variable that holds the unknown name.
func (s *Suite) checkEnvironment(env environment) error {
	for _, c := range []struct {
		name string
		sel  Selection
	}{{EnvID, Selection{IDs: env.narrow.IDs}}, {EnvFamily, Selection{Families: env.narrow.Families}},
		{EnvInstruction, Selection{Instructions: env.narrow.Instructions}}, {EnvTag, Selection{Tags: env.narrow.Tags}},
		{EnvInterpretation, Selection{Interpretations: env.narrow.Interpretations}}} {
		if err := s.checkSelection(c.sel); err != nil {
			return fmt.Errorf("%s=%q: %v", c.name, os.Getenv(c.name), err)
		}
	}
	return nil
}
