ALTER TABLE signalo_db.support
    ADD column picture_2 text;
