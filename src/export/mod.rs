//! Writers of other programs' inputs for a resolved scene (issue 15): [`contact`], CONTACT's
//! module-3 input.

pub mod contact;
