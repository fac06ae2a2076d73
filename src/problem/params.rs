//! The models' own parameters: each model declares the `[model]` keys it reads and validates them
//! once, in its own file (its `ModelDef::params`); the problem holds the results type-erased,
//! a model's builder takes its own back ([`ModelParamSet::get`]), and scene.json's `model` record
//! gets each model's entries after the shared options, in registry order.

use serde::de::{Deserializer, MapAccess, Visitor};
use serde::ser::{SerializeMap, Serializer};
use serde::{Deserialize, Serialize};
use std::any::Any;
use std::fmt;
use std::sync::Arc;

/// A model's validated parameters.
pub trait ModelParams: Any + fmt::Debug + Send + Sync {
    /// Its entries in scene.json's `model` record, in order (none where the scene left the
    /// defaults, as results written before keep them).
    fn scene_json(&self) -> Vec<(&'static str, ParamValue)>;
}

/// One entry of scene.json's `model` record written by a model: a number, or named numbers.
#[derive(Debug, Clone, PartialEq)]
pub enum ParamValue {
    Number(f64),
    Record(Vec<(String, f64)>),
}

/// Every model's parameters, in registry order.
#[derive(Debug, Clone, Default)]
pub struct ModelParamSet(Vec<Arc<dyn ModelParams>>);

impl ModelParamSet {
    pub fn new(params: Vec<Arc<dyn ModelParams>>) -> Self {
        ModelParamSet(params)
    }

    /// The parameters of type `T` (its model's), if they were read.
    pub fn get<T: ModelParams>(&self) -> Option<&T> {
        self.0.iter().find_map(|p| (p.as_ref() as &dyn Any).downcast_ref::<T>())
    }

    /// The entries of scene.json's `model` record, in registry order.
    pub fn scene_json(&self) -> ParamEntries {
        ParamEntries(self.0.iter().flat_map(|p| p.scene_json()).map(|(k, v)| (k.to_string(), v)).collect())
    }
}

/// Entries of scene.json's `model` record written by the models, kept in their order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ParamEntries(pub Vec<(String, ParamValue)>);

impl Serialize for ParamValue {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            ParamValue::Number(x) => s.serialize_f64(*x),
            ParamValue::Record(fields) => {
                let mut map = s.serialize_map(Some(fields.len()))?;
                for (k, v) in fields {
                    map.serialize_entry(k, v)?;
                }
                map.end()
            }
        }
    }
}

impl Serialize for ParamEntries {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in &self.0 {
            map.serialize_entry(k, v)?;
        }
        map.end()
    }
}

struct ValueVisitor;

impl<'de> Visitor<'de> for ValueVisitor {
    type Value = ParamValue;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a number or a record of numbers")
    }
    fn visit_f64<E>(self, v: f64) -> Result<ParamValue, E> {
        Ok(ParamValue::Number(v))
    }
    fn visit_u64<E>(self, v: u64) -> Result<ParamValue, E> {
        Ok(ParamValue::Number(v as f64))
    }
    fn visit_i64<E>(self, v: i64) -> Result<ParamValue, E> {
        Ok(ParamValue::Number(v as f64))
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<ParamValue, A::Error> {
        let mut fields = Vec::new();
        while let Some(entry) = map.next_entry::<String, f64>()? {
            fields.push(entry);
        }
        Ok(ParamValue::Record(fields))
    }
}

impl<'de> Deserialize<'de> for ParamValue {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<ParamValue, D::Error> {
        d.deserialize_any(ValueVisitor)
    }
}

struct EntriesVisitor;

impl<'de> Visitor<'de> for EntriesVisitor {
    type Value = ParamEntries;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("model parameters")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<ParamEntries, A::Error> {
        let mut entries = Vec::new();
        while let Some(entry) = map.next_entry::<String, ParamValue>()? {
            entries.push(entry);
        }
        Ok(ParamEntries(entries))
    }
}

impl<'de> Deserialize<'de> for ParamEntries {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<ParamEntries, D::Error> {
        d.deserialize_map(EntriesVisitor)
    }
}
