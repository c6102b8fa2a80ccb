# Types of Rock's transformer, whose status port a task context's
# transformer block adds. Status samples are read at runtime only: kept as
# plain data.
import_types_from 'base'
accept_unknown_types

opaque 'TransformerStatus'
