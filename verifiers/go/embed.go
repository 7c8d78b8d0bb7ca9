package plcvec

import "embed"

// The compact copy of the golden vectors that `plcvec export --lang go` writes beside this
// file: a program that imports the package has the whole suite, with no checkout and no Python.
//
//go:embed vectors/index.json vectors/*.jsonl
var embedded embed.FS
