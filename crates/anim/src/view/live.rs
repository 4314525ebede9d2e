//! The project a view shows, kept current: loaded with the same `Project::load` as every
//! command, and loaded again when the manifest or its scene file changes on disk. A load
//! that fails keeps the last good project (its frames stay on the page) and records the
//! error exactly as the command line prints it (`animate: file:line:column: message`);
//! the next good load clears it. Each load, good or bad, is a new generation, which
//! waiting pages learn of (`Live::wait`, a long poll).
//!
//! Files are watched with `notify` on their parent folders, not on the files, so that an
//! editor's rename-over save, a deleted and recreated file or a `git checkout` are all
//! seen; events within `DEBOUNCE` of each other make one reload.

use crate::error::AnimError;
use crate::project::draft::Draft;
use crate::project::Project;
use crate::refusal::ManifestError;
use notify::{RecursiveMode, Watcher};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::sync::{Arc, Condvar, Mutex};
use std::time::Duration;

/// Events closer together than this are one change.
pub const DEBOUNCE: Duration = Duration::from_millis(20);
/// The longest a burst of events delays a reload, however long it lasts.
pub const MAX_BURST: Duration = Duration::from_millis(250);

/// One load of the manifest.
#[derive(Clone)]
pub struct Loaded {
    /// Counts loads, good or bad, from 1 (a page learns of each, errors included).
    pub generation: u64,
    /// Counts good loads, from 1 (0: none yet): which project is kept, the key of the
    /// frames drawn from it (a failed load leaves it).
    pub project_id: u64,
    /// The last project that loaded (it stays when a later load fails).
    pub project: Option<Arc<Project>>,
    /// The last load's error, as `animate` prints it; `None` when it loaded.
    pub error: Option<String>,
}

/// The current load, and a way to wait for the next.
pub struct Live {
    manifest: PathBuf,
    draft: Draft,
    state: Mutex<Loaded>,
    changed: Condvar,
}

impl Live {
    /// Loads `manifest` a first time: an error in it is kept (the page shows it), but a
    /// manifest that cannot be read at all is refused (`ManifestError::Io`).
    pub fn new(manifest: &Path) -> Result<Live, AnimError> {
        Live::with_draft(manifest, Draft::default())
    }

    /// `new`, every load with a draft's overrides (`--size`, `--scale`, `--samples`, `--aa`):
    /// frames drawn at the draft's size and settings, the folder's state read from the
    /// draft's folder.
    pub fn with_draft(manifest: &Path, draft: Draft) -> Result<Live, AnimError> {
        let first = Project::load_draft(manifest, &draft);
        if let Err(e @ AnimError::Manifest(ManifestError::Io { .. })) = first {
            return Err(e);
        }
        let live = Live {
            manifest: manifest.to_path_buf(),
            draft,
            state: Mutex::new(Loaded {
                generation: 0,
                project_id: 0,
                project: None,
                error: None,
            }),
            changed: Condvar::new(),
        };
        live.store(first);
        Ok(live)
    }

    /// The manifest's path as given.
    pub fn manifest(&self) -> &Path {
        &self.manifest
    }

    /// Loads the manifest again and wakes every waiting page.
    pub fn reload(&self) {
        self.store(Project::load_draft(&self.manifest, &self.draft));
    }

    /// Makes `result` the current load, a new generation, and wakes every waiting page.
    fn store(&self, result: Result<Project, AnimError>) {
        let mut s = self.lock();
        s.generation += 1;
        match result {
            Ok(p) => {
                s.project = Some(Arc::new(p));
                s.project_id += 1;
                s.error = None;
            }
            Err(e) => s.error = Some(format!("animate: {e}")),
        }
        drop(s);
        self.changed.notify_all();
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Loaded> {
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// The current load.
    pub fn current(&self) -> Loaded {
        self.lock().clone()
    }

    /// Waits until the generation is not `since` (or `timeout` passes); the load then.
    pub fn wait(&self, since: u64, timeout: Duration) -> Loaded {
        let guard = self.lock();
        let (guard, _) = self
            .changed
            .wait_timeout_while(guard, timeout, |s| s.generation == since)
            .unwrap_or_else(|e| e.into_inner());
        guard.clone()
    }

    /// The files whose changes reload: the manifest and the scene it names (the last
    /// good project's, and the one the manifest names now, if it differs).
    fn watched_files(&self) -> BTreeSet<PathBuf> {
        let mut files = BTreeSet::new();
        files.insert(absolute(&self.manifest));
        if let Some(p) = &self.lock().project {
            files.insert(absolute(&p.manifest.scene));
        }
        files
    }
}

/// `path` made absolute with its folder resolved (the file itself may not exist).
fn absolute(path: &Path) -> PathBuf {
    let name = path.file_name().map(PathBuf::from).unwrap_or_default();
    let parent = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    std::fs::canonicalize(&parent).unwrap_or(parent).join(name)
}

/// Watches the folders of the live project's files and reloads it on every change, on a
/// thread of its own, until the process ends. Fails only when the system refuses a
/// watcher.
pub fn watch(live: Arc<Live>) -> notify::Result<()> {
    let (tx, rx) = mpsc::channel::<notify::Result<notify::Event>>();
    let mut watcher = notify::recommended_watcher(tx)?;
    let mut folders = BTreeSet::new();
    let mut files = live.watched_files();
    rewatch(&mut watcher, &files, &mut folders)?;
    std::thread::Builder::new()
        .name("view-watch".into())
        .spawn(move || {
            while let Ok(event) = rx.recv() {
                let mut hit = touches(&event, &files);
                // Debounce: take the events of the burst before loading once, but never
                // longer than `MAX_BURST`: a folder under constant writes would starve it.
                let end = std::time::Instant::now() + MAX_BURST;
                while let Some(left) = end.checked_duration_since(std::time::Instant::now()) {
                    match rx.recv_timeout(left.min(DEBOUNCE)) {
                        Ok(more) => hit |= touches(&more, &files),
                        Err(_) => break,
                    }
                }
                if hit {
                    live.reload();
                    files = live.watched_files();
                    let _ = rewatch(&mut watcher, &files, &mut folders);
                }
            }
        })
        .map_err(notify::Error::io)?;
    Ok(())
}

/// Whether `event` changes one of `files`: a creation, a write, a rename or a removal
/// (not a read, nor a change of times or permissions: the reload's own reading of the
/// files must not trigger another).
fn touches(event: &notify::Result<notify::Event>, files: &BTreeSet<PathBuf>) -> bool {
    use notify::event::{EventKind, ModifyKind};
    match event {
        Ok(e) => {
            let changes = !matches!(
                e.kind,
                EventKind::Access(_)
                    | EventKind::Modify(ModifyKind::Metadata(_))
                    | EventKind::Other
            );
            changes && e.paths.iter().any(|p| files.contains(&absolute(p)))
        }
        // A lost event (an overflowing queue): reload to be sure.
        Err(_) => true,
    }
}

fn rewatch(
    watcher: &mut notify::RecommendedWatcher,
    files: &BTreeSet<PathBuf>,
    folders: &mut BTreeSet<PathBuf>,
) -> notify::Result<()> {
    for f in files {
        if let Some(dir) = f.parent() {
            if folders.insert(dir.to_path_buf()) {
                watcher.watch(dir, RecursiveMode::NonRecursive)?;
            }
        }
    }
    Ok(())
}
