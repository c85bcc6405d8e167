//! One definition usable from every Python thread. The run-time mechanism
//! holds the parser's tokens, which may not cross threads; so each thread
//! that uses a `planar_mechanism.Mechanism` keeps its own copy, read from
//! the same text, in a thread-local table, and the settings (parameters,
//! modes, loads) live here, behind a lock, with a version number: a copy that is
//! behind takes them all again before it is used.

use mechanism_codegen::runtime;
use std::cell::RefCell;
use std::collections::hash_map::Entry;
use std::collections::{BTreeMap, HashMap};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Mutex, PoisonError};

/// The settings every copy follows.
#[derive(Default)]
struct Settings {
    /// Bumped on every change.
    version: u64,
    /// Parameters set at run time, by name.
    params: BTreeMap<String, f64>,
    /// Modes set at run time, by name (`true`: `left`/`plus`).
    modes: BTreeMap<String, bool>,
    /// Load values set at run time, by name.
    loads: BTreeMap<String, f64>,
}

/// A thread's copy of a definition and the settings version it follows.
struct Copy {
    version: u64,
    mechanism: runtime::Mechanism,
}

thread_local! {
    /// This thread's copies, by [`Shared::id`].
    static COPIES: RefCell<HashMap<u64, Copy>> = RefCell::new(HashMap::new());
}

/// The source of the ids.
static NEXT_ID: AtomicU64 = AtomicU64::new(0);

/// A definition read from text, shareable between threads.
pub struct Shared {
    id: u64,
    text: String,
    settings: Mutex<Settings>,
}

impl Shared {
    /// Reads `text`; the errors of the definition as the run-time mechanism
    /// reports them.
    pub fn new(text: &str) -> Result<Self, runtime::Errors> {
        let mechanism = runtime::Mechanism::new(text)?;
        let id = NEXT_ID.fetch_add(1, Ordering::Relaxed);
        let copy = Copy {
            version: 0,
            mechanism,
        };
        COPIES.with(|c| c.borrow_mut().insert(id, copy));
        Ok(Shared {
            id,
            text: text.to_string(),
            settings: Mutex::new(Settings::default()),
        })
    }

    /// `f` of this thread's copy, made (from the text) or brought up to the
    /// settings first. `Err`: the text no longer reads or a setting is
    /// refused (both were checked when made, so neither happens). The lock
    /// on the settings is not held while `f` runs.
    pub fn with<R>(&self, f: impl FnOnce(&mut runtime::Mechanism) -> R) -> Result<R, String> {
        COPIES.with(|copies| {
            let mut copies = copies.borrow_mut();
            let copy = match copies.entry(self.id) {
                Entry::Occupied(e) => e.into_mut(),
                Entry::Vacant(e) => e.insert(Copy {
                    version: u64::MAX,
                    mechanism: runtime::Mechanism::new(&self.text).map_err(|e| e.to_string())?,
                }),
            };
            let behind = {
                let s = self.settings.lock().unwrap_or_else(PoisonError::into_inner);
                (copy.version != s.version).then(|| {
                    let (p, m, l) = (s.params.clone(), s.modes.clone(), s.loads.clone());
                    (s.version, p, m, l)
                })
            };
            if let Some((version, params, modes, loads)) = behind {
                for (name, value) in &params {
                    copy.mechanism.set_param(name, *value)?;
                }
                for (name, left) in &modes {
                    copy.mechanism.set_mode(name, *left)?;
                }
                for (name, value) in &loads {
                    copy.mechanism.set_load(name, *value)?;
                }
                copy.version = version;
            }
            Ok(f(&mut copy.mechanism))
        })
    }

    /// Sets parameter `name` (checked by this thread's copy first).
    pub fn set_param(&self, name: &str, value: f64) -> Result<(), String> {
        self.with(|m| m.set_param(name, value))??;
        self.record(|s| {
            s.params.insert(name.to_string(), value);
        });
        Ok(())
    }

    /// Sets mode `name` (checked by this thread's copy first).
    pub fn set_mode(&self, name: &str, left: bool) -> Result<(), String> {
        self.with(|m| m.set_mode(name, left))??;
        self.record(|s| {
            s.modes.insert(name.to_string(), left);
        });
        Ok(())
    }

    /// Sets load `name` (checked by this thread's copy first).
    pub fn set_load(&self, name: &str, value: f64) -> Result<(), String> {
        self.with(|m| m.set_load(name, value))??;
        self.record(|s| {
            s.loads.insert(name.to_string(), value);
        });
        Ok(())
    }

    /// Records a change already made on this thread's copy: a new version.
    fn record(&self, change: impl FnOnce(&mut Settings)) {
        let mut settings = self.settings.lock().unwrap_or_else(PoisonError::into_inner);
        change(&mut settings);
        let prior = settings.version;
        settings.version += 1;
        let version = settings.version;
        // Current only if no other thread changed a setting in between;
        // else it takes them all again on its next use.
        COPIES.with(|c| {
            if let Some(copy) = c.borrow_mut().get_mut(&self.id) {
                if copy.version == prior {
                    copy.version = version;
                }
            }
        });
    }
}

impl Drop for Shared {
    /// Drops this thread's copy. Copies on other threads stay until those
    /// threads end (a thread cannot reach another's table).
    fn drop(&mut self) {
        // `try_with`: at thread exit the table may already be gone.
        let _ = COPIES.try_with(|c| c.borrow_mut().remove(&self.id));
    }
}
