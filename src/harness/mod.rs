//! Steps 6–7 of the pipeline: comparison against reference and golden data, and the report.
