package plcvec

import (
	"go/ast"
	"go/parser"
	"go/token"
	"io/fs"
	"path/filepath"
	"strings"
	"testing"
)

// maxFunctionLines is the house's bound on a hand-written function (verifiers/VOCABULARY.md, "Functions under 80 lines"),
// declaration and closing brace included. A function that must be longer says why in its doc
// comment, with the words "over 80 lines:".
const maxFunctionLines = 80

// TestFunctionsUnder80Lines: every function of the module, its tests and tools included, is at
// most maxFunctionLines long, or says why not.
func TestFunctionsUnder80Lines(t *testing.T) {
	fset := token.NewFileSet()
	checked := 0
	err := filepath.WalkDir(".", func(path string, d fs.DirEntry, err error) error {
		if err != nil || d.IsDir() || !strings.HasSuffix(path, ".go") {
			return err
		}
		f, err := parser.ParseFile(fset, path, nil, parser.ParseComments)
		if err != nil {
			return err
		}
		for _, decl := range f.Decls {
			fn, ok := decl.(*ast.FuncDecl)
			if !ok || fn.Body == nil {
				continue
			}
			checked++
			lines := fset.Position(fn.End()).Line - fset.Position(fn.Pos()).Line + 1
			if lines > maxFunctionLines && !strings.Contains(fn.Doc.Text(), "over 80 lines:") {
				t.Errorf("%s: %s is %d lines long (at most %d, or say why in its doc comment)",
					fset.Position(fn.Pos()), fn.Name.Name, lines, maxFunctionLines)
			}
		}
		return nil
	})
	if err != nil {
		t.Fatal(err)
	}
	if checked < 100 {
		t.Errorf("only %d functions found under %s: the walk missed the module", checked, ".")
	}
}
