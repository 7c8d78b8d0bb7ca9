module myemu

go 1.22

require plcvec v0.0.0

require github.com/BurntSushi/toml v1.6.0 // indirect

// Until plcvec is published, point the module at a checkout of the repository.
replace plcvec => ../..
