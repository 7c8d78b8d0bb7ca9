package plcvec

import (
	"flag"
	"regexp"
	"strconv"
	"strings"
	"unicode"
)

// runFilter is what `go test -run` and `-skip` let through, worked out as the testing package
// does (testing/match.go): the pattern split at each '/' outside brackets and parentheses, each
// element matched against one level of the subtest's name, '|' between whole patterns. Run needs
// it before it starts any subtest: to tell that -run matches no vector (nothing would be verified,
// a failure that says to use PLCVEC_ID), and to run only the vectors -run selects.
type runFilter struct {
	run, skip [][]*regexp.Regexp // alternatives, each a list of levels; nil run: everything
}

// testFilter is the filter of the current test binary's -test.run and -test.skip flags.
func testFilter() (runFilter, error) {
	var f runFilter
	var err error
	if fl := flag.Lookup("test.run"); fl != nil && fl.Value.String() != "" {
		if f.run, err = splitPattern(fl.Value.String()); err != nil {
			return f, err
		}
	}
	if fl := flag.Lookup("test.skip"); fl != nil && fl.Value.String() != "" {
		if f.skip, err = splitPattern(fl.Value.String()); err != nil {
			return f, err
		}
	}
	return f, nil
}

// pattern is the -run flag's text, for messages.
func runFlag() string {
	if fl := flag.Lookup("test.run"); fl != nil {
		return fl.Value.String()
	}
	return ""
}

// takes reports whether the subtest named name (levels joined by '/') runs.
func (f runFilter) takes(name string) bool {
	levels := strings.Split(name, "/")
	if f.run != nil && !matchAny(f.run, levels, true) {
		return false
	}
	return f.skip == nil || !matchAny(f.skip, levels, false)
}

// matchAny: some alternative matches every level it has; for -skip it must also have a level
// for every level of the name's (a partial match does not skip).
func matchAny(alts [][]*regexp.Regexp, levels []string, partialOK bool) bool {
	for _, alt := range alts {
		ok := true
		for i, l := range levels {
			if i >= len(alt) {
				break
			}
			if !alt[i].MatchString(l) {
				ok = false
				break
			}
		}
		if ok && (partialOK || len(levels) >= len(alt)) {
			return true
		}
	}
	return false
}

// splitPattern splits a -run pattern as testing's splitRegexp does.
func splitPattern(s string) ([][]*regexp.Regexp, error) {
	var alts [][]string
	var cur []string
	brackets, parens := 0, 0
	for i := 0; i < len(s); {
		switch s[i] {
		case '[':
			brackets++
		case ']':
			if brackets--; brackets < 0 {
				brackets = 0
			}
		case '(':
			if brackets == 0 {
				parens++
			}
		case ')':
			if brackets == 0 {
				parens--
			}
		case '\\':
			i++
		case '/', '|':
			if brackets == 0 && parens == 0 {
				cur = append(cur, s[:i])
				if s[i] == '|' {
					alts, cur = append(alts, cur), nil
				}
				s, i = s[i+1:], 0
				continue
			}
		}
		i++
	}
	alts = append(alts, append(cur, s))
	out := make([][]*regexp.Regexp, len(alts))
	for a, levels := range alts {
		for _, l := range levels {
			re, err := regexp.Compile(SubtestName(l))
			if err != nil {
				return nil, err
			}
			out[a] = append(out[a], re)
		}
	}
	return out, nil
}

// SubtestName is the name Go's testing package gives the subtest of a vector id: each space
// becomes '_' and each unprintable character its escape, as testing.T.Run writes it.
func SubtestName(id string) string {
	var b strings.Builder
	for _, r := range id {
		switch {
		case unicode.IsSpace(r):
			b.WriteByte('_')
		case !strconv.IsPrint(r):
			q := strconv.QuoteRune(r)
			b.WriteString(q[1 : len(q)-1])
		default:
			b.WriteRune(r)
		}
	}
	return b.String()
}

// RunPattern is the `go test -run` pattern that selects exactly the vector id under the test
// function test: each '/'-separated level quoted and anchored, as -run matches level by level.
// PLCVEC_ID=<id> is simpler and needs no quoting; RunPattern is for -run alone.
//
//	RunPattern("TestPlcvec", "cp1e-time-compare/AND <=DT/logic/rlo-off/eq")
//	-> ^TestPlcvec$/^cp1e-time-compare$/^AND_<=DT$/^logic$/^rlo-off$/^eq$
func RunPattern(test, id string) string {
	levels := append(strings.Split(test, "/"), strings.Split(SubtestName(id), "/")...)
	for i, l := range levels {
		levels[i] = "^" + regexp.QuoteMeta(l) + "$"
	}
	return strings.Join(levels, "/")
}
