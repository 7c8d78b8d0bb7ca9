package plcvec

// Renamed names, each kept for one minor release after its rename so that code written against
// the release before still builds (CHANGES.md lists each; VOCABULARY.md gives the new names, one
// per concept in every runner). Each is a type alias: the old name is the same type as the new,
// so values pass between code using either.

// Interpretation is the old name of InterpretationInfo.
//
// Deprecated: use InterpretationInfo (package spec's Interpretation is the generated table of the
// same questions); this alias goes in plcvec 0.3.0.
type Interpretation = InterpretationInfo

// Header is the old name of FamilyHeader.
//
// Deprecated: use FamilyHeader; this alias goes in plcvec 0.3.0.
type Header = FamilyHeader

// VectorStep is the old name of Step.
//
// Deprecated: use Step; this alias goes in plcvec 0.3.0.
type VectorStep = Step

// Addr is the old name of Address.
//
// Deprecated: use Address; Addr is removed in 0.4.0.
type Addr = Address
