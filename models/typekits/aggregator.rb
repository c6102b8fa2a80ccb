# Types of the aggregator (Rock's stream aligner), which a task context's
# stream_aligner and transformer blocks use for their status ports. Status
# samples are read at runtime only: kept as plain data.
accept_unknown_types

opaque 'StreamAlignerStatus'
