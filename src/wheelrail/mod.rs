//! The wheel–rail stage: profiles, track and wheelset → contact patches.
//!
//! CONTACT's module 1 (E. Vollebregt's program): the contact of a wheel on a rail given by their
//! profiles. Only the profile stage is here so far ([`profile`]: reading, CONTACT's canonical form,
//! its cleaning and its spline).

pub mod profile;
