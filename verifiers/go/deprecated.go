package plcvec

// Names this release renamed, kept for one minor release so that code written against plcvec
// 0.1.0 still builds (CHANGES.md lists each; VOCABULARY.md gives the new names, one per concept
// in every runner).

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
