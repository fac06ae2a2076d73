//! Readers of other programs' files into this project's formats (issue 32): [`contact`],
//! CONTACT's module-3 input decks → scenes (the mirror of `export`). CONTACT's printed output is a
//! reference and is read in `comparison::references::contact_output`.

pub mod contact;
