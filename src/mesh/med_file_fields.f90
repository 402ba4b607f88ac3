!> The field operations of med_file: fields, their steps and parts, profiles and Gauss point
!> localizations, read and written through the MED server (one request each).
submodule (med_file) med_file_fields
    implicit none

contains
    module procedure med_field_count
        type(message_t) :: q, r
        call q%put_int(OP_FIELD_COUNT)
        n = exchange(file, q, r, 'count', 'its fields', st, writing=.false.)
    end procedure med_field_count

    module procedure med_field_info
        integer, parameter :: CAPACITY = 64
        type(message_t) :: q, r
        character(kind=c_char), allocatable :: name_buffer(:), mesh_buffer(:), buffer(:)
        integer(c_int) :: rc, ncomponent
        integer(i4) :: k
        call q%put_int(OP_FIELD_INFO)
        call q%put_int(int(it))
        call q%put_int(CAPACITY)
        rc = exchange(file, q, r, 'read', 'the description of field ' // to_text(it), st, &
                      writing=.false.)
        call r%get_chars(name_buffer)
        call r%get_chars(mesh_buffer)
        ncomponent = r%get_int()
        call r%get_chars(buffer)
        name = buffer_text(name_buffer, 1, MED_NAME_LEN)
        mesh = buffer_text(mesh_buffer, 1, MED_NAME_LEN)
        allocate (components(0))
        if (st%failed()) return
        deallocate (components)
        allocate (components(max(0, min(ncomponent, CAPACITY))))
        do k = 1, size(components, kind=i4)
            components(k) = buffer_text(buffer, (k - 1) * MED_SNAME_LEN + 1, MED_SNAME_LEN)
        end do
    end procedure med_field_info

    module procedure med_create_field
        type(message_t) :: q, r
        character(len=MED_SNAME_LEN) :: units(size(components))
        integer(c_int) :: rc
        units = ' '
        call q%put_int(OP_CREATE_FIELD)
        call q%put_text(field)
        call q%put_text(mesh)
        call q%put_int(size(components))
        call q%put_chars(fixed_chars(components, MED_SNAME_LEN))
        call q%put_chars(fixed_chars(units, MED_SNAME_LEN))
        rc = exchange(file, q, r, 'create', 'field ' // field, st, writing=.true.)
    end procedure med_create_field

    module procedure med_profile_count
        type(message_t) :: q, r
        call q%put_int(OP_PROFILE_COUNT)
        n = exchange(file, q, r, 'count', 'its profiles', st, writing=.false.)
    end procedure med_profile_count

    module procedure med_write_profile
        type(message_t) :: q, r
        integer(c_int) :: rc
        call q%put_int(OP_WRITE_PROFILE)
        call q%put_text(name)
        call q%put_ints(numbers)
        rc = exchange(file, q, r, 'write', 'profile ' // name, st, writing=.true.)
    end procedure med_write_profile

    module procedure med_write_field_values
        type(message_t) :: q, r
        integer(c_int) :: rc
        call q%put_int(OP_WRITE_FIELD_VALUES)
        call q%put_text(field)
        call q%put_int(int(numdt))
        call q%put_int(int(numit))
        call q%put_real(dt)
        call q%put_int(size(values, 2))
        call q%put_text(profile)
        call q%put_reals(reshape(values, [size(values)]))
        rc = exchange(file, q, r, 'write', 'field ' // field // ' at step ' // &
                      to_text(numdt), st, writing=.true.)
    end procedure med_write_field_values

    module procedure med_localization_names
        type(message_t) :: q, r
        character(kind=c_char), allocatable :: buffer(:)
        integer(c_int) :: n, rc
        integer :: k
        allocate (names(0))
        call q%put_int(OP_LOCALIZATION_COUNT)
        n = exchange(file, q, r, 'count', 'its localisations', st, writing=.false.)
        if (st%failed()) return
        deallocate (names)
        allocate (names(max(n, 0_c_int)))
        do k = 1, size(names)
            call q%clear()
            call q%put_int(OP_LOCALIZATION_NAME)
            call q%put_int(k)
            rc = exchange(file, q, r, 'read', 'localisation ' // to_text(int(k, i4)), st, &
                          writing=.false.)
            if (st%failed()) return
            call r%get_chars(buffer)
            names(k)%s = buffer_text(buffer, 1, MED_NAME_LEN)
        end do
    end procedure med_localization_names

    module procedure med_write_localization
        type(message_t) :: q, r
        integer(c_int) :: rc
        if (size(gscoo, 1) /= size(refcoo, 1) .or. size(gscoo, 2) /= size(weights)) then
            call set_error(st, STATUS_INTERNAL, 'MED file ' // file%path // ': localisation ' &
                // name // ': inconsistent sizes')
            return
        end if
        call q%put_int(OP_WRITE_LOCALIZATION)
        call q%put_text(name)
        call q%put_int(int(geotype))
        call q%put_int(size(refcoo, 1))
        call q%put_reals(reshape(refcoo, [size(refcoo)]))
        call q%put_int(size(weights))
        call q%put_reals(reshape(gscoo, [size(gscoo)]))
        call q%put_reals(weights)
        rc = exchange(file, q, r, 'write', 'localisation ' // name, st, writing=.true.)
    end procedure med_write_localization

    module procedure med_write_entity_values
        type(message_t) :: q, r
        integer(c_int) :: rc
        call q%put_int(OP_WRITE_ENTITY_VALUES)
        call q%put_text(field)
        call q%put_int(int(numdt))
        call q%put_int(int(numit))
        call q%put_real(dt)
        call q%put_int(int(entity))
        call q%put_int(int(geotype))
        call q%put_int(size(values, 2))
        call q%put_text(profile)
        call q%put_text(localization)
        call q%put_reals(reshape(values, [size(values)]))
        rc = exchange(file, q, r, 'write', 'field ' // field // ' at step ' // &
                      to_text(numdt) // ' on cells of MED type ' // to_text(geotype), st, &
                      writing=.true.)
    end procedure med_write_entity_values

    module procedure med_field_steps
        type(message_t) :: q, r
        integer(c_int) :: n, rc
        integer :: k
        allocate (numdt(0), numit(0), dt(0))
        call q%put_int(OP_FIELD_STEP_COUNT)
        call q%put_text(field)
        n = exchange(file, q, r, 'read', 'the steps of field ' // field, st, writing=.false.)
        if (st%failed()) return
        deallocate (numdt, numit, dt)
        allocate (numdt(max(n, 0_c_int)), numit(max(n, 0_c_int)), dt(max(n, 0_c_int)))
        do k = 1, size(numdt)
            call q%clear()
            call q%put_int(OP_FIELD_STEP_INFO)
            call q%put_text(field)
            call q%put_int(k)
            rc = exchange(file, q, r, 'read', 'step ' // to_text(int(k, i4)) // &
                          ' of field ' // field, st, writing=.false.)
            if (st%failed()) return
            numdt(k) = r%get_int()
            numit(k) = r%get_int()
            dt(k) = r%get_real()
        end do
    end procedure med_field_steps

    module procedure med_field_part_count
        type(message_t) :: q, r
        call q%put_int(OP_FIELD_PART_COUNT)
        call q%put_text(field)
        call q%put_int(int(numdt))
        call q%put_int(int(numit))
        call q%put_int(int(entity))
        call q%put_int(int(geotype))
        n = exchange(file, q, r, 'count', 'the parts of field ' // field, st, writing=.false.)
    end procedure med_field_part_count

    module procedure med_field_part_info
        type(message_t) :: q, r
        character(kind=c_char), allocatable :: pbuf(:), lbuf(:)
        integer(c_int) :: n
        profile = ''
        localization = ''
        n_points = 0
        call q%put_int(OP_FIELD_PART_INFO)
        call q%put_text(field)
        call q%put_int(int(numdt))
        call q%put_int(int(numit))
        call q%put_int(int(entity))
        call q%put_int(int(geotype))
        call q%put_int(int(it))
        n = exchange(file, q, r, 'read', 'part ' // to_text(it) // ' of field ' // field, st, &
                     writing=.false.)
        n_entities = n
        if (st%failed()) return
        call r%get_chars(pbuf)
        call r%get_chars(lbuf)
        n_points = r%get_int()
        profile = buffer_text(pbuf, 1, MED_NAME_LEN)
        localization = buffer_text(lbuf, 1, MED_NAME_LEN)
        if (profile == 'MED_NO_PROFILE_INTERNAL') profile = ''
    end procedure med_field_part_info

    module procedure med_read_entity_values
        type(message_t) :: q, r
        real(dp), allocatable :: got(:)
        integer(c_int) :: rc
        values = 0.0_dp
        call q%put_int(OP_READ_ENTITY_VALUES)
        call q%put_text(field)
        call q%put_int(int(numdt))
        call q%put_int(int(numit))
        call q%put_int(int(entity))
        call q%put_int(int(geotype))
        call q%put_text(profile)
        call q%put_int(size(values))
        rc = exchange(file, q, r, 'read', 'the values of field ' // field, st, writing=.false.)
        if (st%failed()) return
        call r%get_reals(got)
        call quiet_signaling_nans(got)
        if (size(got) /= size(values)) then
            call set_error(st, STATUS_INTERNAL, 'MED file ' // file%path // ': field ' // &
                field // ': ' // to_text(size(got)) // ' values read, ' // &
                to_text(size(values)) // ' expected')
            return
        end if
        values = got
    end procedure med_read_entity_values

    module procedure med_read_profile
        type(message_t) :: q, r
        integer(c_int) :: n
        allocate (numbers(0))
        call q%put_int(OP_READ_PROFILE)
        call q%put_text(name)
        call q%put_int(int(capacity))
        n = exchange(file, q, r, 'read', 'profile ' // name, st, writing=.false.)
        if (st%failed()) return
        deallocate (numbers)
        call r%get_ints(numbers)
    end procedure med_read_profile

end submodule med_file_fields
