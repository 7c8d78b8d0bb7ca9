//go:build unix

package faults

import "syscall"

// closeInherited closes every file descriptor from 3 to 1023: what the process inherited or the
// runner opened (its pipe to the parent among them).
func closeInherited() {
	for fd := 3; fd < 1024; fd++ {
		syscall.Close(fd)
	}
}
