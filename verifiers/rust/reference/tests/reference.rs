//! The reference passes every vector under every combination of interpretation alternatives,
//! family by family, the combinations taken from the vector files (never a hard-coded list).

use plcvec::{Choices, OnMemory, Selection, Status, Suite};
use plcvec_reference::Reference;

#[test]
fn the_reference_passes_under_every_combination_of_alternatives() {
    let suite = Suite::embedded().unwrap();
    let mut runs = 0;
    for family in suite.families() {
        let mut combinations: Vec<Vec<(&str, &str)>> = vec![Vec::new()];
        for i in &family.interpretations {
            combinations = combinations
                .into_iter()
                .flat_map(|c| {
                    i.alternatives.iter().map(move |a| {
                        let mut c = c.clone();
                        c.push((i.id.as_str(), a.as_str()));
                        c
                    })
                })
                .collect();
        }
        let selection = Selection::all().family(&family.family);
        for combination in &combinations {
            let choices: Choices = combination.iter().copied().collect();
            let mut reference = OnMemory(Reference::with_choices(choices));
            let report = plcvec::run(&suite, &mut reference, &selection, None).unwrap();
            assert!(report.passed(), "{} under {combination:?}:\n{}", family.family, report.summary());
            assert_eq!(report.count(Status::Pass), report.plan.len());
            runs += 1;
        }
    }
    // At least every alternative of every interpretation was followed once.
    let alternatives: usize =
        suite.families().iter().flat_map(|f| &f.interpretations).map(|i| i.alternatives.len()).sum();
    assert!(runs >= alternatives, "{runs} runs for {alternatives} alternatives");
}
