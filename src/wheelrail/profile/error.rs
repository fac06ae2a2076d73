//! Why a profile is refused: every error names the file (and the line and column where there is
//! one), the value found and what is allowed, with CONTACT's own error number where CONTACT has
//! one (its `m_profile.f90` and `m_errormsg.f90`). Converted into [`InputError`] (exit status 2)
//! the way the crate's other readers are (`import::contact::DeckError`).

use crate::error::InputError;

/// A profile that cannot be read or used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ProfileError {
    /// The path is not a readable regular text file (a directory, a FIFO, a device, too large, not
    /// UTF-8): the bounded reader's message.
    #[error("{file}: {reason}")]
    Unreadable { file: String, reason: String },
    /// A value on one line: a number that is not one, a key's value, a point with too few
    /// coordinates.
    #[error("{file}:{line}:{column}: {what}: {value:?} is not allowed: {allowed}")]
    Value { file: String, line: usize, column: usize, what: String, value: String, allowed: String },
    /// The structure of the file at a line (SIMPACK's sections, the end of the file).
    #[error("{file}:{line}: {what}: allowed: {allowed}")]
    Structure { file: String, line: usize, what: String, allowed: String },
    /// The profile as a whole: too few points, points out of order, a loop, its length.
    #[error("{file}: {what} = {value}: allowed: {allowed}")]
    Profile { file: String, what: String, value: String, allowed: String },
    /// An option of [`super::ProfileOptions`] outside what CONTACT accepts or what is supported.
    #[error("profile option `{field}` = {value}: allowed: {allowed}")]
    Option { field: String, value: String, allowed: String },
}

impl ProfileError {
    /// A whole-profile error on `file`.
    pub(crate) fn profile(
        file: &str,
        what: impl Into<String>,
        value: impl ToString,
        allowed: impl Into<String>,
    ) -> Self {
        ProfileError::Profile {
            file: file.into(),
            what: what.into(),
            value: value.to_string(),
            allowed: allowed.into(),
        }
    }

    /// The error of slice `index` (1-based) of the slices file `slices`: its file named with them.
    pub(crate) fn in_slice(self, slices: &str, index: usize) -> Self {
        let name = |f: String| format!("{slices}, slice {index}: {f}");
        match self {
            ProfileError::Unreadable { file, reason } => ProfileError::Unreadable { file: name(file), reason },
            ProfileError::Value { file, line, column, what, value, allowed } => {
                ProfileError::Value { file: name(file), line, column, what, value, allowed }
            }
            ProfileError::Structure { file, line, what, allowed } => {
                ProfileError::Structure { file: name(file), line, what, allowed }
            }
            ProfileError::Profile { file, what, value, allowed } => {
                ProfileError::Profile { file: name(file), what, value, allowed }
            }
            e @ ProfileError::Option { .. } => e,
        }
    }

    /// An option error.
    pub(crate) fn option(field: &str, value: impl ToString, allowed: impl Into<String>) -> Self {
        ProfileError::Option { field: field.into(), value: value.to_string(), allowed: allowed.into() }
    }
}

impl From<ProfileError> for InputError {
    fn from(e: ProfileError) -> InputError {
        match e {
            ProfileError::Unreadable { file, reason } => {
                InputError::new(file, "unreadable", format!("a readable wheel or rail profile file ({reason})"))
            }
            ProfileError::Value { file, line, column, what, value, allowed } => {
                InputError::new(format!("{file}:{line}:{column} ({what})"), format!("{value:?}"), allowed)
            }
            ProfileError::Structure { file, line, what, allowed } => {
                InputError::new(format!("{file}:{line}"), what, allowed)
            }
            ProfileError::Profile { file, what, value, allowed } => {
                InputError::new(format!("{file} ({what})"), value, allowed)
            }
            ProfileError::Option { field, value, allowed } => InputError::new(field, value, allowed),
        }
    }
}

impl From<ProfileError> for crate::error::Error {
    fn from(e: ProfileError) -> crate::error::Error {
        crate::error::Error::Input(e.into())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_error_becomes_an_input_error_naming_file_line_and_column() {
        let e = ProfileError::Value {
            file: "r.ban".into(),
            line: 7,
            column: 12,
            what: "a point's z".into(),
            value: "abc".into(),
            allowed: "a finite number".into(),
        };
        let input: InputError = e.clone().into();
        assert_eq!(input.field, "r.ban:7:12 (a point's z)");
        assert_eq!(input.value, "\"abc\"");
        let err: crate::error::Error = e.into();
        assert_eq!(err.exit_code(), 2);
        assert!(err.to_string().contains("r.ban:7:12"), "{err}");
    }
}
