module myemu

go 1.22

require github.com/plcvec/plcvec/verifiers/go v0.1.0

require github.com/BurntSushi/toml v1.6.0 // indirect

// This example lives inside the repository and builds against the checkout; a project of your
// own leaves this line out (CI builds the README's example as such a project, from a module proxy).
replace github.com/plcvec/plcvec/verifiers/go => ../..
