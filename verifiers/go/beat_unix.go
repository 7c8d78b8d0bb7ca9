//go:build unix

package plcvec

import (
	"os"
	"sync/atomic"
	"syscall"
	"unsafe"
)

// beat is the child's position, in memory the parent and the child share (a file both map): the
// child writes it twice per vector, with no system call, and it outlives the child, so that the
// parent knows which vector a hung or ended child was on without a line per vector on the pipe.
type beat struct{ mem []byte }

func mapBeat(f *os.File) (*beat, error) {
	mem, err := syscall.Mmap(int(f.Fd()), 0, beatSize, syscall.PROT_READ|syscall.PROT_WRITE, syscall.MAP_SHARED)
	if err != nil {
		return nil, err
	}
	return &beat{mem}, nil
}

// word is the shared position: 2*(i+1) while case i is judged, 2*(i+1)+1 once it is, 0 before any.
func (b *beat) word() *uint64 { return (*uint64)(unsafe.Pointer(&b.mem[0])) } // mmap is page-aligned

// written counts the lines the child has written, stored before the position moves past them.
func (b *beat) written() *uint64 { return (*uint64)(unsafe.Pointer(&b.mem[8])) }

func (b *beat) store(v uint64) { atomic.StoreUint64(b.word(), v) }

func (b *beat) load() uint64 { return atomic.LoadUint64(b.word()) }

func (b *beat) storeWritten(n uint64) { atomic.StoreUint64(b.written(), n) }

func (b *beat) loadWritten() uint64 { return atomic.LoadUint64(b.written()) }

func (b *beat) unmap() { syscall.Munmap(b.mem) }
