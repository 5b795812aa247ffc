ALTER TABLE signalo_db.vl_coating DROP COLUMN IF EXISTS value_en;
ALTER TABLE signalo_db.vl_coating DROP COLUMN IF EXISTS description_en;

ALTER TABLE signalo_db.vl_durability DROP COLUMN IF EXISTS value_en;
ALTER TABLE signalo_db.vl_durability DROP COLUMN IF EXISTS description_en;

ALTER TABLE signalo_db.vl_frame_fixing_type DROP COLUMN IF EXISTS value_en;
ALTER TABLE signalo_db.vl_frame_fixing_type DROP COLUMN IF EXISTS description_en;

ALTER TABLE signalo_db.vl_frame_type DROP COLUMN IF EXISTS value_en;
ALTER TABLE signalo_db.vl_frame_type DROP COLUMN IF EXISTS description_en;

ALTER TABLE signalo_db.vl_lighting DROP COLUMN IF EXISTS value_en;
ALTER TABLE signalo_db.vl_lighting DROP COLUMN IF EXISTS description_en;

ALTER TABLE signalo_db.vl_marker_type DROP COLUMN IF EXISTS value_en;
ALTER TABLE signalo_db.vl_marker_type DROP COLUMN IF EXISTS description_en;

ALTER TABLE signalo_db.vl_mirror_shape DROP COLUMN IF EXISTS value_en;
ALTER TABLE signalo_db.vl_mirror_shape DROP COLUMN IF EXISTS description_en;

ALTER TABLE signalo_db.vl_sign_type DROP COLUMN IF EXISTS value_en;
ALTER TABLE signalo_db.vl_sign_type DROP COLUMN IF EXISTS description_en;

ALTER TABLE signalo_db.vl_status DROP COLUMN IF EXISTS value_en;
ALTER TABLE signalo_db.vl_status DROP COLUMN IF EXISTS description_en;

ALTER TABLE signalo_db.vl_support_base_type DROP COLUMN IF EXISTS value_en;
ALTER TABLE signalo_db.vl_support_base_type DROP COLUMN IF EXISTS description_en;

ALTER TABLE signalo_db.vl_support_type DROP COLUMN IF EXISTS value_en;
ALTER TABLE signalo_db.vl_support_type DROP COLUMN IF EXISTS description_en;
