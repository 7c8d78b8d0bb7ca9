package plcvec

import (
	"go/ast"
	"go/parser"
	"go/token"
	"reflect"
	"strings"
	"testing"
)

// TestAddrIsAddress: code written against the old name keeps building and means the same: Addr
// is Address itself (an alias), so values pass between the two names, the methods are the same,
// and Memory takes either.
func TestAddrIsAddress(t *testing.T) {
	if reflect.TypeOf(Addr{}) != reflect.TypeOf(Address{}) {
		t.Fatalf("Addr is %v, Address is %v: not one type", reflect.TypeOf(Addr{}), reflect.TypeOf(Address{}))
	}
	var old Addr = ParseAddr("D100")
	var now Address = old.Offset(2)
	if now != (Address{Kind: "D", N: 102}) || old.String() != "D100" || now.String() != "D102" {
		t.Errorf("Addr D100: Offset(2) = %v (%s), String = %s; want {D 102} (D102), D100", now, now, old)
	}
	mem := NewMemory(NewRequest("t", "f", "I", nil, map[string]Value{"D7": Word(0)}, map[string]Operand{}, nil, []Inputs{{}}))
	mem.SetWord(Addr{Kind: "D", N: 7}, 42)
	if got := mem.Word(Address{Kind: "D", N: 7}); got != 42 {
		t.Errorf("a word set at Addr D7 reads %d at Address D7, want 42", got)
	}
}

// TestDeprecatedNamesSayWhatReplacesThem: every old name in deprecated.go is an alias of the new
// one (so it is the same type, not a copy) and carries the "Deprecated:" paragraph that go doc,
// gopls and staticcheck (SA1019) read, naming the new name and the release that removes it.
func TestDeprecatedNamesSayWhatReplacesThem(t *testing.T) {
	f, err := parser.ParseFile(token.NewFileSet(), "deprecated.go", nil, parser.ParseComments)
	if err != nil {
		t.Fatal(err)
	}
	seen := map[string]bool{}
	for _, decl := range f.Decls {
		gen, ok := decl.(*ast.GenDecl)
		if !ok || gen.Tok != token.TYPE {
			continue
		}
		for _, spec := range gen.Specs {
			ts := spec.(*ast.TypeSpec)
			seen[ts.Name.Name] = true
			target, ok := ts.Type.(*ast.Ident)
			if !ts.Assign.IsValid() || !ok {
				t.Errorf("deprecated.go: %s is not an alias of a type of this package", ts.Name.Name)
				continue
			}
			if !deprecatedParagraph(gen.Doc.Text(), target.Name, " 0.3.0", " 0.4.0") {
				t.Errorf("deprecated.go: %s has no paragraph \"Deprecated: use %s ... <the release that removes it>\"\n%s", ts.Name.Name, target.Name, gen.Doc.Text())
			}
		}
	}
	if !seen["Addr"] {
		t.Error("deprecated.go does not keep Addr, the old name of Address, which stays until 0.4.0")
	}
}

// deprecatedParagraph reports whether doc has a paragraph "Deprecated: use <name>" (the name
// whole, not the start of a longer one) that names one of the releases.
func deprecatedParagraph(doc, name string, releases ...string) bool {
	for _, p := range strings.Split(doc, "\n\n") {
		p = strings.Join(strings.Fields(p), " ")
		rest, ok := strings.CutPrefix(p, "Deprecated: use "+name)
		if !ok || rest == "" || !strings.ContainsRune(" ;,(", rune(rest[0])) {
			continue
		}
		for _, r := range releases {
			if strings.Contains(p, r) {
				return true
			}
		}
	}
	return false
}
