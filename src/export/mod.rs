//! Writers of other programs' inputs for a resolved scene (issue 15): [`contact`], CONTACT's
//! module-3 input; [`wheelrail`], CONTACT's module-1 input for a wheel–rail scene (issue 44).

pub mod contact;
pub mod wheelrail;
