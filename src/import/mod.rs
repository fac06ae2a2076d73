//! Readers of other programs' inputs (issue 32): [`contact`], CONTACT's module-3 input decks →
//! scenes. The mirror of `export`.

pub mod contact;
