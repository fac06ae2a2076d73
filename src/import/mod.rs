//! Readers of other programs' files into this project's formats (issue 32): [`contact`],
//! CONTACT's module-3 input decks → scenes (the mirror of `export`); [`contact_output`], the
//! totals CONTACT prints per case.

pub mod contact;
pub mod contact_output;
