//! The digest of a case's whole input (`run.json`'s and `shard.json`'s input hash, through
//! the runner): the typed case document after reading, serialized by serde (so that no field
//! can be left out: every field of every table struct is in its serialization, a quantity as
//! its SI value), its mechanisms' own tables, and the bytes of every file the case reads.

use serde_json::Value;
use std::sync::{Arc, LazyLock};

/// FNV-1a, 128 bits (Fowler, Noll and Vo; IETF draft-eastlake-fnv, section 2 and the 128-bit
/// offset basis and prime of section 5): a stable hash of the inputs, the same in every build
/// and on every machine (std's hasher promises neither). It tells inputs apart, it is no
/// protection against someone forging a collision.
#[derive(Clone, Copy)]
pub struct Fnv(u128);

impl Default for Fnv {
    fn default() -> Self {
        Self(0x6c62_272e_07bb_0142_62b8_2175_6295_c58d)
    }
}

impl Fnv {
    /// Hashes `bytes` in, then a separator, so that ("ab", "c") and ("a", "bc") differ.
    pub fn update(&mut self, bytes: &[u8]) -> &mut Self {
        const PRIME: u128 = 0x0000_0000_0100_0000_0000_0000_0000_013b;
        for &b in bytes.iter().chain(&[0xff]) {
            self.0 ^= u128::from(b);
            self.0 = self.0.wrapping_mul(PRIME);
        }
        self
    }

    /// The hash as 32 hexadecimal digits.
    pub fn hex(&self) -> String {
        format!("{:032x}", self.0)
    }
}

/// The digest of a case's whole input, made when it is first read (issue 37: a point of a sweep
/// written as a table is validated and run, its digest never read; making it was 2.5 % of the
/// point's time): the hash of its document's canonical bytes ([`canonical`]), then of the name
/// and digest of each file it read. Its clones share it, made once. It shows (`{:?}`) as the
/// digest's text does, which the runner's input hash reads.
#[derive(Clone)]
pub struct InputDigest(Arc<LazyLock<String, Box<dyn FnOnce() -> String + Send>>>);

impl InputDigest {
    /// The digest of `document` (the typed case as read, and its mechanisms' tables) and the
    /// files it read (`files`: each as named, and the digest of its bytes), in that order.
    pub fn new<T>(document: T, files: Vec<(String, String)>) -> Self
    where
        T: serde::Serialize + Send + 'static,
    {
        Self(Arc::new(LazyLock::new(Box::new(move || {
            let mut digest = Fnv::default();
            digest.update(&canonical(&document));
            for (name, bytes) in &files {
                digest.update(name.as_bytes()).update(bytes.as_bytes());
            }
            digest.hex()
        }))))
    }

    /// The digest as 32 hexadecimal digits.
    pub fn hex(&self) -> &str {
        LazyLock::force(&self.0).as_str()
    }
}

impl std::fmt::Debug for InputDigest {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Debug::fmt(self.hex(), f)
    }
}

/// The hash of `bytes` alone (a file's content).
pub fn of_bytes(bytes: &[u8]) -> String {
    Fnv::default().update(bytes).hex()
}

/// The canonical bytes of `value`'s serialization: JSON with every object's keys sorted (the
/// order a TOML table was written in does not change the input).
pub fn canonical<T: serde::Serialize>(value: &T) -> Vec<u8> {
    fn sorted(v: Value) -> Value {
        match v {
            Value::Object(map) => {
                let mut entries: Vec<(String, Value)> = map.into_iter().collect();
                entries.sort_by(|a, b| a.0.cmp(&b.0));
                Value::Object(entries.into_iter().map(|(k, v)| (k, sorted(v))).collect())
            }
            Value::Array(items) => Value::Array(items.into_iter().map(sorted).collect()),
            v => v,
        }
    }
    // The typed case serializes into JSON whatever it holds (strings, numbers, tables).
    let value = serde_json::to_value(value).unwrap_or_else(|e| Value::String(e.to_string()));
    serde_json::to_vec(&sorted(value)).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// FNV-1a 128 of the empty string is its offset basis; of "a" (with our separator byte
    /// after it) it differs from "a" followed by anything else.
    #[test]
    fn the_hash_is_stable_and_separates_parts() {
        assert_eq!(Fnv::default().hex(), "6c62272e07bb014262b821756295c58d");
        let ab_c = Fnv::default().update(b"ab").update(b"c").hex();
        let a_bc = Fnv::default().update(b"a").update(b"bc").hex();
        assert_ne!(ab_c, a_bc);
        assert_eq!(ab_c, Fnv::default().update(b"ab").update(b"c").hex());
    }

    /// The digest made when read is the hash of the document's canonical bytes, then of each
    /// file's name and digest (as it was made at validation before issue 37), and shows as its
    /// text does (the runner's input hash reads the case's `{:?}`); its clones share it.
    #[test]
    fn the_digest_made_when_read_is_the_digest_of_the_input() {
        let document: toml::Table = toml::from_str("x = 1.5\ny = { b = \"2 mm\" }").unwrap();
        let files = vec![("trace.csv".to_string(), of_bytes(b"0,1\n"))];
        let mut eager = Fnv::default();
        eager.update(&canonical(&document));
        eager.update(b"trace.csv").update(files[0].1.as_bytes());
        let lazy = InputDigest::new(document.clone(), files.clone());
        let copy = lazy.clone();
        assert_eq!(lazy.hex(), eager.hex());
        assert_eq!(format!("{lazy:?}"), format!("{:?}", eager.hex()));
        assert!(std::ptr::eq(lazy.hex(), copy.hex()));
        assert_ne!(InputDigest::new(document, Vec::new()).hex(), eager.hex());
    }

    /// A table's keys in another order are the same input.
    #[test]
    fn the_order_of_keys_does_not_count() {
        let a: toml::Table = toml::from_str("x = 1\ny = { b = 2, a = 3 }").unwrap();
        let b: toml::Table = toml::from_str("y = { a = 3, b = 2 }\nx = 1").unwrap();
        assert_eq!(canonical(&a), canonical(&b));
        let c: toml::Table = toml::from_str("y = { a = 3, b = 2 }\nx = 2").unwrap();
        assert_ne!(canonical(&a), canonical(&c));
    }
}
