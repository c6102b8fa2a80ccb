# The types of Rock's gps_base typekit this app's drivers use. They are
# declared opaque: their values are not checked, but their names are.
opaque 'Solution'
opaque 'UTMConversionParameters'
