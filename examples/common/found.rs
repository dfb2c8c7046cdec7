//! What a survey's limit-state search found, as two table cells, shared by the speed
//! examples.

use arch_enum::limit_states::Survey;

/// (how many limit states: the one at η_s if it carries a mechanism, and those above;
/// the method and its event count), or ("-", why the search is undecided).
pub fn found(sv: &Survey) -> (String, String) {
    match &sv.states {
        Ok(ls) => (
            format!("{}", usize::from(ls.mechanism_at_eta_s) + ls.above.len()),
            format!("{}, {}", ls.method, ls.events),
        ),
        Err(e) => ("-".into(), format!("undecided: {e}")),
    }
}
