module github.com/plcvec/plcvec/verifiers/go

go 1.22

require github.com/BurntSushi/toml v1.6.0
