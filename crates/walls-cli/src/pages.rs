//! The memory pages a run's process is given. mimalloc asks Linux for 2 MiB pages
//! (transparent huge pages) for its arenas, which makes linting a large walls file a
//! quarter faster (fewer page faults) but keeps partly used 2 MiB pages resident: a run
//! of 10⁵ particles peaked at 91–94 MiB with them and 84–86 MiB without, in the same time
//! (docs/performance-history.md, "Eighth round"). `walls-sim run` therefore asks for ordinary
//! pages; the other commands keep the large ones.

/// From here on, this process's memory comes in ordinary pages (Linux's
/// `PR_SET_THP_DISABLE`, which holds for the whole process and its children: in the
/// Python wheel, the console script's interpreter); elsewhere, or if the kernel
/// refuses, nothing changes.
pub fn ordinary() {
    #[cfg(any(target_os = "linux", target_os = "android"))]
    {
        // Refused only by kernels older than 3.15: the run is the same, larger.
        let _ = rustix::thread::disable_transparent_huge_pages(true);
    }
}

#[cfg(all(test, any(target_os = "linux", target_os = "android")))]
mod tests {
    #[test]
    fn after_it_the_process_is_given_no_huge_pages() {
        super::ordinary();
        assert_eq!(
            rustix::thread::transparent_huge_pages_are_disabled().ok(),
            Some(true)
        );
    }
}
