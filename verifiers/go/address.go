package plcvec

import (
	"strconv"
	"strings"
)

// Address is a device address split into its kind and number: D100 is {"D", 100}, SM709 is
// {"SM", 709}. A name without a number (Omron's P_EQ, P_ER) has N = -1. Multi-word operands
// occupy consecutive numbers, which Offset gives without building strings.
type Address struct {
	Kind string
	N    int
}

// ParseAddr splits a device name: trailing decimal digits are the number.
func ParseAddr(name string) Address {
	i := len(name)
	for i > 0 && name[i-1] >= '0' && name[i-1] <= '9' {
		i--
	}
	if i == len(name) || i == 0 {
		return Address{Kind: name, N: -1}
	}
	n, err := strconv.Atoi(name[i:])
	if err != nil {
		return Address{Kind: name, N: -1}
	}
	return Address{Kind: name[:i], N: n}
}

// Offset is the address k points further: D100.Offset(2) is D102.
func (a Address) Offset(k int) Address { return Address{Kind: a.Kind, N: a.N + k} }

// String is the device name: D102.
func (a Address) String() string {
	if a.N < 0 {
		return a.Kind
	}
	var b strings.Builder
	b.WriteString(a.Kind)
	b.WriteString(strconv.Itoa(a.N))
	return b.String()
}
