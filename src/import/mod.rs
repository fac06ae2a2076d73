//! Readers of other programs' files into this project's formats (issue 32): [`contact_output`],
//! the totals CONTACT prints per case.

pub mod contact_output;
