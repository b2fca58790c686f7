"""The protocols of the draft-plate and no-draft papers, run on copies of
openfoam_cases/spoutDraftPlates; each module's main(argv) is the command
protocols/<name> of that case."""
