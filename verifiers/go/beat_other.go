//go:build !unix

package plcvec

import (
	"errors"
	"os"
)

// beat needs memory shared with the child (beat_unix.go); elsewhere Run judges in process
// (canIsolate), so this is never reached.
type beat struct{}

func mapBeat(*os.File) (*beat, error) {
	return nil, errors.New("no memory shared with a child process here")
}

func (*beat) store(uint64) {}

func (*beat) load() uint64 { return 0 }

func (*beat) storeWritten(uint64) {}

func (*beat) loadWritten() uint64 { return 0 }

func (*beat) unmap() {}
