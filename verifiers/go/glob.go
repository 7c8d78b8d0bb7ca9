package plcvec

import (
	"fmt"
	"regexp"
	"strings"
	"sync"
)

// Id globs follow Python's fnmatch, as the other plcvec runners do: * matches any run of
// characters including '/', ? one character, [abc] and [!abc] a set. path.Match is not used
// because its * stops at '/', and every id is made of '/'-separated parts.

var globCache sync.Map // pattern -> *regexp.Regexp

func compileGlob(pattern string) (*regexp.Regexp, error) {
	if g, ok := globCache.Load(pattern); ok {
		return g.(*regexp.Regexp), nil
	}
	var b strings.Builder
	b.WriteString(`^(?s:`)
	for i := 0; i < len(pattern); i++ {
		c := pattern[i]
		if c >= 0x80 { // a multi-byte character: copy it whole, literally
			j := i + 1
			for j < len(pattern) && pattern[j]&0xC0 == 0x80 {
				j++
			}
			b.WriteString(regexp.QuoteMeta(pattern[i:j]))
			i = j - 1
			continue
		}
		switch c {
		case '*':
			b.WriteString(`.*`)
		case '?':
			b.WriteString(`.`)
		case '[':
			j := i + 1
			if j < len(pattern) && pattern[j] == '!' {
				j++
			}
			if j < len(pattern) && pattern[j] == ']' {
				j++
			}
			for j < len(pattern) && pattern[j] != ']' {
				j++
			}
			if j >= len(pattern) { // no closing bracket: a literal '[' as fnmatch reads it
				b.WriteString(`\[`)
				continue
			}
			set := strings.ReplaceAll(pattern[i+1:j], `\`, `\\`)
			if strings.HasPrefix(set, "!") {
				set = "^" + set[1:]
			} else if strings.HasPrefix(set, "^") {
				set = `\` + set
			}
			b.WriteString("[" + set + "]")
			i = j
		default:
			b.WriteString(regexp.QuoteMeta(string(c)))
		}
	}
	b.WriteString(`)$`)
	g, err := regexp.Compile(b.String())
	if err != nil {
		return nil, fmt.Errorf("id pattern %q: %v", pattern, err)
	}
	globCache.Store(pattern, g)
	return g, nil
}
