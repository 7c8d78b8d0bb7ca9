//! Declaring the interpretation alternatives an implementation follows.
//!
//! Where the manual is silent a vector carries its expectation under every alternative; an
//! implementation declares its alternative per interpretation id, and is judged by the matching
//! entry (CONTRACT.md, "Declaring your interpretation"). Undeclared interpretations take the
//! default. The alternatives are generated enums (`names::Fx5Sm709Scope::AllWords`), so a
//! declaration cannot be misspelt.

use std::collections::BTreeMap;

/// An alternative of one interpretation: implemented by each generated interpretation enum.
pub trait Alternative: Copy + Sized + 'static {
    /// The interpretation id (`FX5-SM709-SCOPE`).
    const ID: &'static str;
    /// The alternative that holds when none is declared.
    const DEFAULT: Self;
    /// Every alternative.
    const ALL: &'static [Self];
    /// The alternative's id (`all-words`).
    fn as_str(self) -> &'static str;

    /// The alternative with this id.
    fn from_name(name: &str) -> Option<Self> {
        Self::ALL.iter().copied().find(|a| a.as_str() == name)
    }
}

/// interpretation id -> alternative id, as declared.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Choices {
    declared: BTreeMap<String, String>,
}

impl Choices {
    /// Nothing declared: every interpretation takes its default.
    pub fn new() -> Choices {
        Choices::default()
    }

    /// Declare `alternative` (builder style): `Choices::new().with(Fx5Sm709Scope::AllWords)`.
    pub fn with<A: Alternative>(mut self, alternative: A) -> Choices {
        self.declare(A::ID, alternative.as_str());
        self
    }

    /// Declare an alternative by its ids (from a command line or a config file). Whether the
    /// suite has them is checked when a run starts.
    pub fn declare(&mut self, interpretation: &str, alternative: &str) {
        self.declared.insert(interpretation.to_owned(), alternative.to_owned());
    }

    /// The declared alternative of `A`'s interpretation, or its default. A declared id that
    /// this build does not know (a newer vector copy) also gives the default; runs refuse
    /// such declarations before anything is judged.
    pub fn get<A: Alternative>(&self) -> A {
        self.declared.get(A::ID).and_then(|name| A::from_name(name)).unwrap_or(A::DEFAULT)
    }

    /// The declared alternative of an interpretation, if any.
    pub fn declared(&self, interpretation: &str) -> Option<&str> {
        self.declared.get(interpretation).map(String::as_str)
    }

    /// Every declaration, sorted by interpretation id.
    pub fn iter(&self) -> impl Iterator<Item = (&str, &str)> {
        self.declared.iter().map(|(i, a)| (i.as_str(), a.as_str()))
    }

    /// Whether nothing is declared.
    pub fn is_empty(&self) -> bool {
        self.declared.is_empty()
    }
}

impl<'a> FromIterator<(&'a str, &'a str)> for Choices {
    fn from_iter<T: IntoIterator<Item = (&'a str, &'a str)>>(iter: T) -> Choices {
        let mut choices = Choices::new();
        for (i, a) in iter {
            choices.declare(i, a);
        }
        choices
    }
}

/// The alternative followed for one interpretation.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Followed {
    /// The interpretation id.
    pub interpretation: String,
    /// The alternative.
    pub alternative: String,
    /// Whether the implementation declared it (else it is the default).
    pub declared: bool,
}
